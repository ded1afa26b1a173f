import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, plain, point } from './arbitraries.test-helpers';
import { lagrangeBasis, lagrangePoint } from './lagrange';

describe('lagrangeBasis', () => {
  it('is 1 at its own node and 0 at the others', () => {
    expect(plain(lagrangeBasis([0, 1, 2], 1))).toEqual([0, 1, 0]);
    expect(lagrangeBasis([0, 0.5, 1], 0.25)).toEqual([0.375, 0.75, -0.125]);
  });

  it('sums to one for any t (it reproduces constants)', () => {
    const nodes = fc.uniqueArray(fc.integer({ min: -20, max: 20 }), { minLength: 1, maxLength: 7 });
    fc.assert(
      fc.property(nodes, fc.double({ min: -25, max: 25, noNaN: true }), (ts, t) => {
        const sum = lagrangeBasis(ts, t).reduce((a, b) => a + b, 0);
        expect(sum).toBeCloseTo(1, 3);
      }),
    );
  });
});

describe('lagrangePoint', () => {
  it('passes through every given point', () => {
    fc.assert(
      fc.property(
        fc.uniqueArray(fc.integer({ min: -10, max: 10 }), { minLength: 1, maxLength: 6 }),
        fc.array(point(3), { minLength: 6, maxLength: 6 }),
        (ts, all) => {
          const points = all.slice(0, ts.length);
          ts.forEach((t, k) => expectClose(lagrangePoint(ts, points, t), points[k], 1e-9));
        },
      ),
    );
  });

  it('reproduces a quadratic exactly, also outside the nodes', () => {
    const f = (t: number) => [t * t - 2 * t + 3, 5 * t];
    const ts = [0, 1, 3];
    expectClose(lagrangePoint(ts, ts.map(f), 2), f(2), 1e-12);
    expectClose(lagrangePoint(ts, ts.map(f), -4), f(-4), 1e-12);
  });

  it('rejects coincident parameters, mismatched lengths and non-finite t', () => {
    expect(() => lagrangePoint([0, 1, 1], [[0], [1], [2]], 0.5)).toThrow(
      /ts\[1\] and ts\[2\] are both 1/,
    );
    expect(() => lagrangePoint([0, 1], [[0], [1], [2]], 0.5)).toThrow(
      /ts has 2 entries but points has 3/,
    );
    expect(() => lagrangePoint([0, 1], [[0], [1]], NaN)).toThrow(/t is NaN/);
    expect(() => lagrangeBasis([], 0)).toThrow(/at least 1 value/);
  });
});
