import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, polygon2D } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { cubicSelfIntersection } from './cubicSelfIntersection';

describe('cubicSelfIntersection', () => {
  it('finds the crossing of a loop', () => {
    const points = [
      [0, 0],
      [5, 3],
      [-1, 3],
      [4, 0],
    ];
    const found = cubicSelfIntersection(points);
    expect(found).not.toBeNull();
    const [t, s] = found!;
    expect(t).toBeLessThan(s);
    expectClose(bezierPoint(points, t), bezierPoint(points, s), 1e-12);
  });

  it('finds the symmetric crossing of a symmetric loop', () => {
    // x = 3t(1−t)·(… ) symmetric about x = 0.5: the crossing is at t + s = 1.
    const [t, s] = cubicSelfIntersection([
      [0, 0],
      [2, 2],
      [-1, 2],
      [1, 0],
    ])!;
    expect(t + s).toBeCloseTo(1, 12);
  });

  it('finds none on an arch, an S-curve, a line or a point', () => {
    const curves = [
      [
        [0, 0],
        [1, 2],
        [3, 2],
        [4, 0],
      ],
      [
        [0, 0],
        [1, 1],
        [2, -1],
        [3, 0],
      ],
      [
        [0, 0],
        [1, 1],
        [2, 2],
        [3, 3],
      ],
      [
        [2, 2],
        [2, 2],
        [2, 2],
        [2, 2],
      ],
    ];
    for (const curve of curves) expect(cubicSelfIntersection(curve)).toBeNull();
  });

  it('any crossing it reports is a real one, inside [0, 1]', () => {
    fc.assert(
      fc.property(polygon2D(4, 4), (points) => {
        const found = cubicSelfIntersection(points);
        if (!found) return;
        const [t, s] = found;
        expect(0 <= t && t < s && s <= 1).toBe(true);
        const scale = Math.max(1, ...points.flat().map(Math.abs));
        const a = bezierPoint(points, t);
        const b = bezierPoint(points, s);
        expect(Math.hypot(a[0] - b[0], a[1] - b[1])).toBeLessThan(1e-7 * scale);
      }),
    );
  });

  it('rejects anything but a 2D cubic', () => {
    expect(() =>
      cubicSelfIntersection([
        [0, 0],
        [1, 1],
      ]),
    ).toThrow(RangeError);
  });
});
