import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bsplineBasis, clampedUniformKnots, uniformKnots } from './bsplineBasis';

const knotVector = fc
  .tuple(
    fc.integer({ min: 0, max: 4 }),
    fc.array(fc.integer({ min: 0, max: 5 }), { minLength: 2, maxLength: 14 }),
  )
  .map(([degree, steps]) => {
    const knots = [0];
    for (const step of steps) knots.push(knots[knots.length - 1] + step);
    return { degree, knots };
  })
  .filter(({ degree, knots }) => knots.length >= degree + 2 && knots[knots.length - 1] > knots[0]);

describe('bsplineBasis', () => {
  it('is the indicator of [knots[i], knots[i+1]) at degree 0, closed at the very end', () => {
    const knots = [0, 1, 2, 3];
    expect(bsplineBasis(knots, 0, 0, 0)).toBe(1);
    expect(bsplineBasis(knots, 0, 0, 1)).toBe(0);
    expect(bsplineBasis(knots, 0, 1, 1)).toBe(1);
    expect(bsplineBasis(knots, 0, 2, 3)).toBe(1);
  });

  it('gives the hat function at degree 1 and the quadratic pieces at degree 2', () => {
    expect(bsplineBasis([0, 1, 2], 1, 0, 0.5)).toBe(0.5);
    expect(bsplineBasis([0, 1, 2], 1, 0, 1)).toBe(1);
    expect(bsplineBasis([0, 1, 2], 1, 0, 1.5)).toBe(0.5);
    // Uniform quadratic: t²/2 on [0,1], (−2t² + 6t − 3)/2 on [1,2], (3 − t)²/2 on [2,3].
    expect(bsplineBasis([0, 1, 2, 3], 2, 0, 0.5)).toBe(0.125);
    expect(bsplineBasis([0, 1, 2, 3], 2, 0, 1.5)).toBe(0.75);
    expect(bsplineBasis([0, 1, 2, 3], 2, 0, 2.5)).toBe(0.125);
  });

  it('is non-negative and sums to one on the interior [knots[p], knots[n+1]]', () => {
    fc.assert(
      fc.property(
        knotVector,
        fc.double({ min: 0, max: 1, noNaN: true }),
        ({ degree, knots }, fraction) => {
          const count = knots.length - degree - 1;
          const [low, high] = [knots[degree], knots[count]];
          fc.pre(high > low);
          const t = low + fraction * (high - low);
          let sum = 0;
          for (let i = 0; i < count; i++) {
            const value = bsplineBasis(knots, degree, i, t);
            expect(value).toBeGreaterThanOrEqual(0);
            sum += value;
          }
          expect(sum).toBeCloseTo(1, 12);
        },
      ),
    );
  });

  it('reaches 1 for the last function at the end of a clamped vector', () => {
    const knots = clampedUniformKnots(5, 3);
    expect(knots).toEqual([0, 0, 0, 0, 0.5, 1, 1, 1, 1]);
    expect(bsplineBasis(knots, 3, 4, 1)).toBe(1);
    expect(bsplineBasis(knots, 3, 0, 0)).toBe(1);
  });

  it('rejects bad knots, degree, index and t', () => {
    expect(() => bsplineBasis([0, 2, 1], 0, 0, 0.5)).toThrow(
      /knots\[2\] = 1 is less than knots\[1\] = 2/,
    );
    expect(() => bsplineBasis([0, 1], 2, 0, 0.5)).toThrow(/needs at least 4 values/);
    expect(() => bsplineBasis([0, 1, 2], 1, 1, 0.5)).toThrow(/i = 1 is too large/);
    expect(() => bsplineBasis([0, 1, 2], 1, 0, 2.5)).toThrow(
      /t = 2.5 is outside the allowed range \[0, 2\]/,
    );
    expect(() => bsplineBasis([1, 1, 1], 1, 0, 1)).toThrow(/non-empty interval/);
    expect(() => bsplineBasis([0, 1, 2], -1, 0, 1)).toThrow(/degree/);
  });
});

describe('knot vector helpers', () => {
  it('build clamped and uniform vectors', () => {
    expect(clampedUniformKnots(3, 2)).toEqual([0, 0, 0, 1, 1, 1]);
    expect(clampedUniformKnots(6, 2)).toEqual([0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1]);
    expect(uniformKnots(4, 3)).toEqual([0, 1, 2, 3, 4, 5, 6, 7]);
    expect(() => clampedUniformKnots(2, 2)).toThrow(/pointCount/);
  });
});
