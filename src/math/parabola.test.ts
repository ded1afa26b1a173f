import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, plain, point, unitParameter } from './arbitraries.test-helpers';
import { parabolaThrough, parametricQuadratic, parametricQuadraticPoint } from './parabola';
import { centripetalMu, chordLengthMu, parameterValues } from './parameterisation';

const openMu = fc.double({ min: 0.01, max: 0.99, noNaN: true });

describe('parabolaThrough', () => {
  it('finds y = x² through (0, 0), (1, 1), (2, 4)', () => {
    expect(parabolaThrough([0, 0], [1, 1], [2, 4])).toEqual([0, 0, 1]);
    expect(parabolaThrough([-1, 6], [0, 3], [2, 3])).toEqual([3, -2, 1]);
  });

  it('passes through its three points, even with x near 1e6', () => {
    const x = fc.double({ min: -1e3, max: 1e3, noNaN: true });
    fc.assert(
      fc.property(
        fc.uniqueArray(x, {
          minLength: 3,
          maxLength: 3,
          comparator: (a, b) => Math.abs(a - b) < 1e-3,
        }),
        fc.array(x, { minLength: 3, maxLength: 3 }),
        (xs, ys) => {
          const [a0, a1, a2] = parabolaThrough([xs[0], ys[0]], [xs[1], ys[1]], [xs[2], ys[2]]);
          xs.forEach((value, i) =>
            expect(a0 + a1 * value + a2 * value * value).toBeCloseTo(ys[i], 3),
          );
        },
      ),
    );
    const [a0, a1, a2] = parabolaThrough([1e6, 0], [1e6 + 1, 1], [1e6 + 2, 4]);
    // y = (x − 1e6)² expanded: a2 = 1, a1 = −2e6, a0 = 1e12.
    expect(a2).toBeCloseTo(1, 6);
    expect(a1 / -2e6).toBeCloseTo(1, 9);
    expect(a0 / 1e12).toBeCloseTo(1, 9);
  });

  it('rejects coincident abscissae and non-2D points', () => {
    expect(() => parabolaThrough([1, 0], [1, 2], [3, 4])).toThrow(/p0 and p1 have the same x = 1/);
    expect(() => parabolaThrough([0, 0], [1, 2], [1, 4])).toThrow(/p1 and p2 have the same x = 1/);
    expect(() => parabolaThrough([0, 0, 0], [1, 2], [2, 4])).toThrow(/p0 has 3 coordinates but 2/);
  });
});

describe('parametricQuadratic', () => {
  it('passes through p0 at 0, p1 at mu and p2 at 1', () => {
    fc.assert(
      fc.property(
        fc.constantFrom(2, 3).chain((d) => fc.tuple(point(d), point(d), point(d))),
        openMu,
        ([p0, p1, p2], mu) => {
          const [a0, a1, a2] = parametricQuadratic(p0, p1, p2, mu);
          const at = (t: number) => a0.map((_, d) => a0[d] + a1[d] * t + a2[d] * t * t);
          expectClose(at(0), p0);
          expectClose(at(mu), p1, 1e-6);
          expectClose(at(1), p2, 1e-6);
          expectClose(parametricQuadraticPoint(p0, p1, p2, mu, mu), p1, 1e-12);
          expectClose(parametricQuadraticPoint(p0, p1, p2, mu, 0), p0, 1e-12);
          expectClose(parametricQuadraticPoint(p0, p1, p2, mu, 1), p2, 1e-12);
        },
      ),
    );
  });

  it('agrees with its evaluation helper', () => {
    fc.assert(
      fc.property(
        fc.tuple(point(2), point(2), point(2)),
        openMu,
        unitParameter,
        ([p0, p1, p2], mu, t) => {
          const [a0, a1, a2] = parametricQuadratic(p0, p1, p2, mu);
          expectClose(
            parametricQuadraticPoint(p0, p1, p2, mu, t),
            a0.map((_, d) => a0[d] + a1[d] * t + a2[d] * t * t),
            1e-6,
          );
        },
      ),
    );
  });

  it('gives the lecture example with mu = 1/2', () => {
    // Through (0,0), (1,1), (2,0) at μ = 0, 1/2, 1: P(μ) = (2μ, 4μ − 4μ²).
    expect(parametricQuadratic([0, 0], [1, 1], [2, 0], 0.5).map(plain)).toEqual([
      [0, 0],
      [2, 4],
      [0, -4],
    ]);
  });

  it('rejects mu outside (0, 1)', () => {
    for (const mu of [0, 1, -0.5, 1.5, NaN]) {
      expect(() => parametricQuadratic([0, 0], [1, 1], [2, 0], mu)).toThrow(
        /mu = .* is outside the allowed range \(0, 1\)/,
      );
    }
  });
});

describe('parameter choices', () => {
  it('chord length uses |P1 − P0| / (|P1 − P0| + |P2 − P1|), centripetal their square roots', () => {
    expect(chordLengthMu([0, 0], [3, 4], [3, 5])).toBe(5 / 6);
    expect(centripetalMu([0, 0], [4, 0], [4, 1])).toBe(2 / 3);
    expect(chordLengthMu([1, 1], [1, 1], [1, 1])).toBe(0.5);
  });

  it('gives parameter values from 0 to 1 with gaps |ΔP|^alpha', () => {
    const points = [
      [0, 0],
      [3, 4],
      [3, 5],
      [3, 14],
    ];
    expect(parameterValues(points, 0)).toEqual([0, 1 / 3, 2 / 3, 1]);
    expect(parameterValues(points, 1)).toEqual([0, 5 / 15, 6 / 15, 1]);
    expect(parameterValues(points, 0.5)).toEqual([
      0,
      Math.sqrt(5) / (Math.sqrt(5) + 4),
      (Math.sqrt(5) + 1) / (Math.sqrt(5) + 4),
      1,
    ]);
    expect(
      parameterValues(
        [
          [2, 2],
          [2, 2],
          [2, 2],
        ],
        1,
      ),
    ).toEqual([0, 0.5, 1]);
    expect(() => parameterValues(points, 2)).toThrow(/alpha = 2 is outside/);
  });
});
