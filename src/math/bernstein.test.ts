import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bernstein, bernsteinBasis } from './bernstein';

const degree = fc.integer({ min: 0, max: 30 });
const parameter = fc.double({ min: 0, max: 1, noNaN: true });

describe('bernstein', () => {
  it('gives the cubic blending functions of the lecture at t = 1/2', () => {
    expect([0, 1, 2, 3].map((i) => bernstein(3, i, 0.5))).toEqual([1 / 8, 3 / 8, 3 / 8, 1 / 8]);
  });

  it('is exact at t = 0 and t = 1 (0⁰ = 1)', () => {
    for (let n = 0; n <= 10; n++) {
      for (let i = 0; i <= n; i++) {
        expect(bernstein(n, i, 0)).toBe(i === 0 ? 1 : 0);
        expect(bernstein(n, i, 1)).toBe(i === n ? 1 : 0);
      }
    }
  });

  it('is 0 for i outside 0 … n', () => {
    expect(bernstein(3, -1, 0.5)).toBe(0);
    expect(bernstein(3, 4, 0.5)).toBe(0);
  });

  it('is a non-negative partition of unity', () => {
    fc.assert(
      fc.property(degree, parameter, (n, t) => {
        let sum = 0;
        for (let i = 0; i <= n; i++) {
          const value = bernstein(n, i, t);
          expect(value).toBeGreaterThanOrEqual(0);
          sum += value;
        }
        expect(sum).toBeCloseTo(1, 12);
      }),
    );
  });

  it('agrees with bernsteinBasis', () => {
    fc.assert(
      fc.property(degree, parameter, (n, t) => {
        const basis = bernsteinBasis(n, t);
        expect(basis).toHaveLength(n + 1);
        basis.forEach((value, i) => expect(value).toBeCloseTo(bernstein(n, i, t), 12));
      }),
    );
  });

  it('rejects a parameter outside [0, 1] or a bad degree', () => {
    expect(() => bernstein(3, 1, 1.5)).toThrow(/t = 1.5 is outside the allowed range \[0, 1\]/);
    expect(() => bernstein(3, 1, NaN)).toThrow(RangeError);
    expect(() => bernstein(-1, 0, 0.5)).toThrow(RangeError);
    expect(() => bernstein(3, 0.5, 0.5)).toThrow(RangeError);
    expect(() => bernsteinBasis(3, -0.1)).toThrow(RangeError);
  });
});
