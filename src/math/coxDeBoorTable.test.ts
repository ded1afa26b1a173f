import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bsplineBasis, knotSpan } from './bsplineBasis';
import { coxDeBoorTable } from './coxDeBoorTable';

// Non-decreasing integer knot vectors (repeated knots included) with a degree
// they support, and a t anywhere in [knots[0], knots[last]].
const knotsAndT = fc
  .tuple(
    fc.integer({ min: 0, max: 4 }),
    fc.array(fc.integer({ min: 0, max: 3 }), { minLength: 1, maxLength: 12 }),
    fc.double({ min: 0, max: 1, noNaN: true }),
  )
  .map(([degree, steps, fraction]) => {
    const knots = [0];
    for (const step of steps) knots.push(knots[knots.length - 1] + step);
    const last = knots[knots.length - 1];
    return { degree, knots, t: fraction * last };
  })
  .filter(({ degree, knots }) => knots.length >= degree + 2 && knots[knots.length - 1] > 0);

describe('coxDeBoorTable', () => {
  it('builds the triangle worked out by hand', () => {
    // Uniform knots, t = 1.5 in [1, 2): N(1,0) = 1; N(0,1) = N(1,1) = 0.5;
    // N(0,2) = (1.5/2)·0.5 + (1.5/2)·0.5 = 0.75.
    expect(coxDeBoorTable([0, 1, 2, 3], 2, 1.5)).toEqual([[0, 1, 0], [0.5, 0.5], [0.75]]);
    // Clamped cubic at t = 1/2: rows narrow to the Bernstein weights 1/8, 3/8, 3/8, 1/8.
    expect(coxDeBoorTable([0, 0, 0, 0, 1, 1, 1, 1], 3, 0.5)).toEqual([
      [0, 0, 0, 1, 0, 0, 0],
      [0, 0, 0.5, 0.5, 0, 0],
      [0, 0.25, 0.5, 0.25, 0],
      [0.125, 0.375, 0.375, 0.125],
    ]);
    // Degree 0 is row 0 alone; at the last knot the last non-empty interval is closed.
    expect(coxDeBoorTable([0, 1, 2, 3], 0, 3)).toEqual([[0, 0, 1]]);
    expect(coxDeBoorTable([0, 0, 1, 1], 1, 1)).toEqual([
      [0, 1, 0],
      [0, 1],
    ]);
    // A repeated inner knot: N(1,0) is the empty interval [1, 1), always 0.
    expect(coxDeBoorTable([0, 1, 1, 2], 1, 0.25)).toEqual([
      [1, 0, 0],
      [0.25, 0],
    ]);
  });

  it('ends in the row of bsplineBasis, value for value', () => {
    fc.assert(
      fc.property(knotsAndT, ({ degree, knots, t }) => {
        const rows = coxDeBoorTable(knots, degree, t);
        expect(rows).toHaveLength(degree + 1);
        rows.forEach((row, r) => expect(row).toHaveLength(knots.length - r - 1));
        rows[degree].forEach((value, i) => {
          // === rather than toBe: the same number, whatever the sign of a zero.
          expect(value === bsplineBasis(knots, degree, i, t)).toBe(true);
        });
      }),
    );
  });

  it('has one 1 in row 0, then non-negative rows that sum to 1 where they cover t', () => {
    fc.assert(
      fc.property(knotsAndT, ({ degree, knots, t }) => {
        const rows = coxDeBoorTable(knots, degree, t);
        const span = knotSpan('test', knots, t);
        expect(rows[0].map((value, i) => (i === span ? value === 1 : value === 0))).not.toContain(
          false,
        );
        rows.forEach((row, r) => {
          // Only N(span − r … span, r) can be non-zero, and row r is a partition
          // of unity on [knots[r], knots[length − r − 1]] when that is not empty.
          row.forEach((value, i) => {
            expect(value).toBeGreaterThanOrEqual(0);
            if (i < span - r || i > span) expect(value).toBe(0);
          });
          const [low, high] = [knots[r], knots[knots.length - r - 1]];
          if (low < high && low <= t && t <= high) {
            expect(row.reduce((sum, value) => sum + value, 0)).toBeCloseTo(1, 12);
          }
        });
      }),
    );
  });

  it('rejects what bsplineBasis rejects', () => {
    expect(() => coxDeBoorTable([0, 1, 2], 1, 2.5)).toThrow(
      'coxDeBoorTable: t = 2.5 is outside the allowed range [0, 2].',
    );
    expect(() => coxDeBoorTable([0, 2, 1], 1, 0.5)).toThrow(/knots\[2\] = 1 is less than/);
    expect(() => coxDeBoorTable([0, 1, 2], 2, 0.5)).toThrow(/at least 4 values, but got 3/);
    expect(() => coxDeBoorTable([0, 1, 2], -1, 0.5)).toThrow(/degree is -1/);
    expect(() => coxDeBoorTable([0, 1, 2], 0.5, 0.5)).toThrow(/whole number/);
    expect(() => coxDeBoorTable([1, 1, 1], 1, 1)).toThrow(/every knot is 1/);
    expect(() => coxDeBoorTable([0, NaN, 2], 1, 1)).toThrow(RangeError);
  });
});
