import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bezierArcLength } from './arcLength';
import { bezierArcLengthTable, bezierParameterAtLength } from './arcLengthParameter';

describe('bezierArcLengthTable', () => {
  it('on a line with uniform control points s = 3t exactly', () => {
    const line = [
      [0, 0],
      [1, 0],
      [2, 0],
      [3, 0],
    ];
    const rows = bezierArcLengthTable(line, 4);
    expect(rows.map((r) => r.t)).toEqual([0, 0.25, 0.5, 0.75, 1]);
    rows.forEach((r) => expect(r.s).toBeCloseTo(3 * r.t, 12));
  });

  it('on a line with doubled ends s(t) = x(t) = 9t² − 6t³', () => {
    // Control points 0, 0, 3, 3 on the x axis: x(t) = 3·3t²(1 − t) + 3t³.
    const slow = [
      [0, 0],
      [0, 0],
      [3, 0],
      [3, 0],
    ];
    for (const r of bezierArcLengthTable(slow, 5))
      expect(r.s).toBeCloseTo(9 * r.t ** 2 - 6 * r.t ** 3, 12);
  });

  it('refuses a count that is not a whole number ≥ 1', () => {
    expect(() =>
      bezierArcLengthTable(
        [
          [0, 0],
          [1, 1],
        ],
        0,
      ),
    ).toThrow(RangeError);
    expect(() =>
      bezierArcLengthTable(
        [
          [0, 0],
          [1, 1],
        ],
        1.5,
      ),
    ).toThrow(RangeError);
  });
});

describe('bezierParameterAtLength', () => {
  const slow = [
    [0, 0],
    [0, 0],
    [3, 0],
    [3, 0],
  ];

  it('inverts s(t) = 9t² − 6t³ where it is known by hand', () => {
    // s(1/2) = 9/4 − 6/8 = 3/2 (the curve's middle, by symmetry); s(1) = 3.
    expect(bezierParameterAtLength(slow, 1.5)).toBeCloseTo(0.5, 12);
    expect(bezierParameterAtLength(slow, 0)).toBe(0);
    expect(bezierParameterAtLength(slow, 3)).toBe(1);
    // s(1/4) = 9/16 − 6/64 = 30/64 = 0.46875.
    expect(bezierParameterAtLength(slow, 0.46875)).toBeCloseTo(0.25, 12);
  });

  it('s(t(s)) = s on random cubics', () => {
    const point = fc.tuple(
      fc.double({ min: -10, max: 10, noNaN: true }),
      fc.double({ min: -10, max: 10, noNaN: true }),
    );
    fc.assert(
      fc.property(
        fc.array(point, { minLength: 4, maxLength: 4 }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (points, fraction) => {
          const total = bezierArcLength(points, 1);
          fc.pre(total > 1e-3);
          const t = bezierParameterAtLength(points, fraction * total);
          expect(t).toBeGreaterThanOrEqual(0);
          expect(t).toBeLessThanOrEqual(1);
          expect(Math.abs(bezierArcLength(points, t) - fraction * total)).toBeLessThan(
            1e-9 * total,
          );
        },
      ),
      { numRuns: 60 },
    );
  });

  it('refuses a length outside [0, L]', () => {
    expect(() => bezierParameterAtLength(slow, -0.1)).toThrow(RangeError);
    expect(() => bezierParameterAtLength(slow, 3.5)).toThrow(/between 0 and/);
  });
});
