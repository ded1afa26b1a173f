import { describe, expect, it } from 'vitest';
import { bezierPoint } from './bezier';
import { rationalBezierPoint, sampleRationalBezier } from './rationalBezier';
import type { Point } from './vec';

// The quarter circle as a rational quadratic: corners (1,0), (1,1), (0,1) with weights 1, √2/2, 1.
const arc: Point[] = [
  [1, 0],
  [1, 1],
  [0, 1],
];
const arcWeights = [1, Math.SQRT1_2, 1];

describe('rationalBezierPoint', () => {
  it('is the Bézier curve when all weights are equal', () => {
    const cubic: Point[] = [
      [0, 0],
      [1, 2],
      [3, 2],
      [4, 0],
    ];
    for (const t of [0, 0.3, 0.5, 1]) {
      const p = rationalBezierPoint(cubic, [2, 2, 2, 2], t);
      const q = bezierPoint(cubic, t);
      expect(p[0]).toBeCloseTo(q[0], 14);
      expect(p[1]).toBeCloseTo(q[1], 14);
    }
  });

  it('draws the quarter circle: the middle is (√2/2, √2/2)', () => {
    // At t = ½: numerator (¼(1,0) + ½·(√2/2)(1,1) + ¼(0,1)), denominator ½ + √2/4.
    const middle = rationalBezierPoint(arc, arcWeights, 0.5);
    expect(middle[0]).toBeCloseTo(Math.SQRT1_2, 14);
    expect(middle[1]).toBeCloseTo(Math.SQRT1_2, 14);
    for (const t of [0.1, 0.25, 0.8]) {
      const [x, y] = rationalBezierPoint(arc, arcWeights, t);
      expect(Math.hypot(x, y)).toBeCloseTo(1, 14);
    }
  });

  it('refuses a weight that is not positive', () => {
    expect(() => rationalBezierPoint(arc, [1, 0, 1], 0.5)).toThrow(/weights\[1\] = 0/);
    expect(() => rationalBezierPoint(arc, [1, 1], 0.5)).toThrow(RangeError);
  });
});

describe('sampleRationalBezier', () => {
  it('samples the same points as rationalBezierPoint, ends exact', () => {
    const samples = sampleRationalBezier(arc, arcWeights, 4);
    expect(samples).toHaveLength(10);
    expect([samples[0], samples[1]]).toEqual([1, 0]);
    expect([samples[8], samples[9]]).toEqual([0, 1]);
    const quarter = rationalBezierPoint(arc, arcWeights, 0.25);
    expect(samples[2]).toBeCloseTo(quarter[0], 15);
    expect(samples[3]).toBeCloseTo(quarter[1], 15);
  });
});
