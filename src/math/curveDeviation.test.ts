import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { polygon } from './arbitraries.test-helpers';
import { elevateDegree } from './bezier';
import { bezierDeviation, sampledDeviation } from './curveDeviation';

describe('bezierDeviation', () => {
  it('is zero for a curve and its degree-elevated form', () => {
    fc.assert(
      fc.property(polygon(1, 8), (points) => {
        const scale = Math.max(1, ...points.flat().map(Math.abs));
        expect(bezierDeviation(points, elevateDegree(points), 200).distance).toBeLessThan(
          1e-12 * scale,
        );
      }),
    );
  });

  it('moving one control point by Δ moves the curve at most W(n,i,i/n)·|Δ|, at t = i/n', () => {
    // Cubic, P1 moved by (0, 3): the curve moves 3·W(3,1,t), largest at t = 1/3: 3·4/9.
    const before = [
      [0, 0],
      [1, 2],
      [3, 2],
      [4, 0],
    ];
    const after = [
      [0, 0],
      [1, 5],
      [3, 2],
      [4, 0],
    ];
    const { at, distance } = bezierDeviation(before, after, 999);
    expect(at).toBeCloseTo(1 / 3, 12);
    expect(distance).toBeCloseTo(4 / 3, 12);
  });

  it('rejects mismatched dimensions', () => {
    expect(() => bezierDeviation([[0, 0]], [[0, 0, 0]])).toThrow(RangeError);
  });
});

describe('sampledDeviation', () => {
  it('finds the farthest pair and its index', () => {
    expect(sampledDeviation([0, 0, 1, 1, 2, 2], [0, 0, 1, 4, 2, 3])).toEqual({
      at: 1,
      distance: 3,
    });
  });

  it('rejects arrays of different lengths and non-finite samples', () => {
    expect(() => sampledDeviation([0, 0], [0, 0, 1, 1])).toThrow(RangeError);
    expect(() => sampledDeviation([0, NaN], [0, 0])).toThrow(RangeError);
  });
});
