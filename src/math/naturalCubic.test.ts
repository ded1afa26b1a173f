import { curveNatural } from 'd3-shape';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, polygon } from './arbitraries.test-helpers';
import { cubicSplineC2 } from './bezierSpline';
import {
  closedCubicSystem,
  closedCubicTangents,
  naturalCubicDerivativesClosed,
} from './closedCubic';
import { closedCubicSplinePoint, cubicSplinePoint } from './cubicSpline';
import { hermiteBasisDerivatives } from './hermite';
import {
  clampedCubicDerivatives,
  clampedCubicSystem,
  clampedCubicTangents,
  naturalCubicCoefficients,
  naturalCubicDerivatives,
  naturalCubicSystem,
  naturalCubicTangents,
  sampleNaturalCubicSpline,
} from './naturalCubic';
import { naturalCubicBezierBatch, naturalCubicDerivativesBatch } from './naturalCubicBatch';
import { solveTridiagonal } from './tridiagonal';
import type { Point } from './vec';
import { recordD3Bezier } from './d3Reference.test-helpers';

const values = (minimum: number, maximum = 30) =>
  fc.array(fc.double({ min: -100, max: 100, noNaN: true }), {
    minLength: minimum,
    maxLength: maximum,
  });

/** Second derivative of the Hermite segment (y0, D0, y1, D1) at local t. */
function secondDerivative(y0: number, d0: number, y1: number, d1: number, t: number): number {
  const [h0, h1, h2, h3] = hermiteBasisDerivatives(t, 2);
  return h0 * y0 + h1 * y1 + h2 * d0 + h3 * d1;
}

describe('naturalCubicSystem', () => {
  it('is the lecture’s matrix [2 1], [1 4 1], [1 2] with rhs 3(y1−y0), 3(y(i+1)−y(i−1)), 3(ym−y(m−1))', () => {
    expect(naturalCubicSystem([0, 1, 0, 1])).toEqual({
      sub: [0, 1, 1, 1],
      diag: [2, 4, 4, 2],
      sup: [1, 1, 1, 0],
      rhs: [3, 0, 0, 3],
    });
    expect(naturalCubicSystem([2, 5])).toEqual({
      sub: [0, 1],
      diag: [2, 2],
      sup: [1, 0],
      rhs: [9, 9],
    });
  });
});

describe('naturalCubicDerivatives', () => {
  it('solves ys = [0, 1, 0] to D = [3/2, 0, −3/2] and ys = [0, 1, 0, 1] to [5/3, −1/3, −1/3, 5/3]', () => {
    expect(naturalCubicDerivatives([0, 1, 0])).toEqual([1.5, 0, -1.5]);
    const d = naturalCubicDerivatives([0, 1, 0, 1]);
    [5 / 3, -1 / 3, -1 / 3, 5 / 3].forEach((value, i) => expect(d[i]).toBeCloseTo(value, 14));
  });

  it('handles one and two values', () => {
    expect(naturalCubicDerivatives([7])).toEqual([0]);
    expect(naturalCubicDerivatives([1, 4])).toEqual([3, 3]);
  });

  it('agrees with the general Thomas solver on the displayed system', () => {
    fc.assert(
      fc.property(values(2, 200), (ys) => {
        const { sub, diag, sup, rhs } = naturalCubicSystem(ys);
        const reference = solveTridiagonal(sub, diag, sup, rhs);
        naturalCubicDerivatives(ys).forEach((value, i) =>
          expect(Math.abs(value - reference[i])).toBeLessThan(1e-10),
        );
      }),
    );
  });

  it('satisfies its equations, is C² at every joint and has zero second derivative at both ends', () => {
    fc.assert(
      fc.property(values(2), (ys) => {
        const D = naturalCubicDerivatives(ys);
        const m = ys.length - 1;
        const close = (a: number, b: number) => expect(Math.abs(a - b)).toBeLessThan(1e-9);
        close(2 * D[0] + D[1], 3 * (ys[1] - ys[0]));
        close(D[m - 1] + 2 * D[m], 3 * (ys[m] - ys[m - 1]));
        for (let i = 1; i < m; i++)
          close(D[i - 1] + 4 * D[i] + D[i + 1], 3 * (ys[i + 1] - ys[i - 1]));
        close(secondDerivative(ys[0], D[0], ys[1], D[1], 0), 0);
        close(secondDerivative(ys[m - 1], D[m - 1], ys[m], D[m], 1), 0);
        for (let i = 1; i < m; i++) {
          close(
            secondDerivative(ys[i - 1], D[i - 1], ys[i], D[i], 1),
            secondDerivative(ys[i], D[i], ys[i + 1], D[i + 1], 0),
          );
        }
      }),
    );
  });

  it('is accurate for values near 1e6 and near 1e-6', () => {
    const ys = [0, 1, 0, 1];
    const big = naturalCubicDerivatives(ys.map((y) => 1e6 + y));
    [5 / 3, -1 / 3, -1 / 3, 5 / 3].forEach((value, i) => expect(big[i]).toBeCloseTo(value, 9));
    const tiny = naturalCubicDerivatives(ys.map((y) => 1e-6 * y));
    [5 / 3, -1 / 3, -1 / 3, 5 / 3].forEach((value, i) =>
      expect(Math.abs(tiny[i] / 1e-6 - value)).toBeLessThan(1e-12),
    );
  });

  it('rejects no values and non-finite values', () => {
    expect(() => naturalCubicDerivatives([])).toThrow(/ys needs at least 1 value, but got 0/);
    expect(() => naturalCubicDerivatives([0, NaN])).toThrow(/ys\[1\] is NaN/);
    expect(() => naturalCubicDerivatives([0, 1, -Infinity])).toThrow(RangeError);
  });

  it('rejects what is not a number, and values whose gradients overflow', () => {
    const bad = (ys: unknown) => () => naturalCubicDerivatives(ys as number[]);
    expect(bad([0, '1', 2])).toThrow('naturalCubicDerivatives: ys[1] is a string;');
    expect(bad([0, null, 2])).toThrow('naturalCubicDerivatives: ys[1] is null;');
    expect(bad([0, 1, , 3])).toThrow('naturalCubicDerivatives: ys[2] is undefined;'); // eslint-disable-line no-sparse-arrays
    expect(bad(null)).toThrow(
      'naturalCubicDerivatives: ys is null; it must be an array of numbers.',
    );
    expect(bad([-1e308, 1e308, -1e308])).toThrow(/so large that the result overflows/);
  });

  it('returns a fresh array of numbers, whatever the input array holds', () => {
    const integers = [0, 3, 1, 4];
    const result = naturalCubicDerivatives(integers);
    expect(Array.isArray(result)).toBe(true);
    expect(result).not.toBe(integers);
    expect(integers).toEqual([0, 3, 1, 4]);
    expect(naturalCubicDerivatives(Float64Array.of(0, 3, 1, 4) as unknown as number[])).toEqual(
      result,
    );
  });
});

describe('clampedCubicDerivatives', () => {
  it('keeps the given end gradients and solves the inner rows', () => {
    // D0 = 2, D2 = −1, row D0 + 4D1 + D2 = 3(y2 − y0) = 0 → D1 = −1/4.
    expect(clampedCubicDerivatives([0, 1, 0], 2, -1)).toEqual([2, -0.25, -1]);
    expect(clampedCubicDerivatives([0, 5], 1, 2)).toEqual([1, 2]);
  });

  it('displays its system with identity end rows', () => {
    expect(clampedCubicSystem([0, 1, 0], 2, -1)).toEqual({
      sub: [0, 1, 0],
      diag: [1, 4, 1],
      sup: [0, 1, 0],
      rhs: [2, 0, -1],
    });
  });

  it('is C² at inner joints and equals the natural spline when given its end gradients', () => {
    fc.assert(
      fc.property(values(3), (ys) => {
        const natural = naturalCubicDerivatives(ys);
        const m = ys.length - 1;
        const clamped = clampedCubicDerivatives(ys, natural[0], natural[m]);
        clamped.forEach((value, i) => expect(Math.abs(value - natural[i])).toBeLessThan(1e-9));
      }),
    );
  });

  it('needs two values and finite gradients', () => {
    expect(() => clampedCubicDerivatives([1], 0, 0)).toThrow(/at least 2 values/);
    expect(() => clampedCubicDerivatives([1, 2], NaN, 0)).toThrow(/d0 is NaN/);
  });
});

describe('naturalCubicDerivativesClosed', () => {
  it('solves ys = [0, 1, 0, 2] to D = [−3/4, 0, 3/4, 0]', () => {
    const d = naturalCubicDerivativesClosed([0, 1, 0, 2]);
    [-0.75, 0, 0.75, 0].forEach((value, i) => expect(d[i]).toBeCloseTo(value, 14));
    expect(closedCubicSystem([0, 1, 0, 2]).rhs).toEqual([-3, 0, 3, 0]);
  });

  it('satisfies every cyclic equation and is C² all round, including the closing joint', () => {
    fc.assert(
      fc.property(values(3), (ys) => {
        const D = naturalCubicDerivativesClosed(ys);
        const n = ys.length;
        for (let i = 0; i < n; i++) {
          const [before, after] = [(i + n - 1) % n, (i + 1) % n];
          expect(
            Math.abs(D[before] + 4 * D[i] + D[after] - 3 * (ys[after] - ys[before])),
          ).toBeLessThan(1e-9);
          expect(
            Math.abs(
              secondDerivative(ys[before], D[before], ys[i], D[i], 1) -
                secondDerivative(ys[i], D[i], ys[after], D[after], 0),
            ),
          ).toBeLessThan(1e-8);
        }
      }),
    );
  });

  it('needs three values', () => {
    expect(() => naturalCubicDerivativesClosed([0, 1])).toThrow(/at least 3 values/);
  });
});

describe('tangent helpers on points', () => {
  it('work per coordinate, in 2D and 3D', () => {
    fc.assert(
      fc.property(polygon(1, 12), (points) => {
        const tangents = naturalCubicTangents(points);
        for (let d = 0; d < points[0].length; d++) {
          const expected = naturalCubicDerivatives(points.map((p) => p[d]));
          tangents.forEach((tangent, i) => expect(tangent[d]).toBeCloseTo(expected[i], 9));
        }
      }),
    );
  });

  it('clamped tangents start and end with the given vectors', () => {
    fc.assert(
      fc.property(
        polygon(2, 10).chain((points) =>
          fc.tuple(fc.constant(points), point(points[0].length), point(points[0].length)),
        ),
        ([points, start, end]) => {
          const tangents = clampedCubicTangents(points, start, end);
          expect(tangents[0]).toEqual(start);
          expect(tangents[tangents.length - 1]).toEqual(end);
        },
      ),
    );
  });

  it('closed tangents make a closed curve with matching ends', () => {
    const square: Point[] = [
      [0, 0],
      [1, 0],
      [1, 1],
      [0, 1],
    ];
    const tangents = closedCubicTangents(square);
    expectClose(closedCubicSplinePoint(square, tangents, 4), square[0]);
    expectClose(
      closedCubicSplinePoint(square, tangents, 2.5),
      cubicSplinePoint(square, tangents, 2.5),
    );
    // Try D_i = c(P(i+1) − P(i−1)): around a square P(i+2) = P(i−2), so the row
    // D(i−1) + 4D_i + D(i+1) becomes 4c(P(i+1) − P(i−1)) = 3(P(i+1) − P(i−1)),
    // c = 3/4, and at P0 the tangent is 3/4 ((1, 0) − (0, 1)).
    expectClose(tangents[0], [0.75, -0.75]);
  });

  it('reject mismatched tangent dimensions', () => {
    expect(() =>
      clampedCubicTangents(
        [
          [0, 0],
          [1, 1],
        ],
        [1, 0, 0],
        [1, 0],
      ),
    ).toThrow(/startTangent has 3 coordinates but 2 are expected/);
    expect(() =>
      closedCubicTangents([
        [0, 0],
        [1, 1],
      ]),
    ).toThrow(/at least 3 points/);
  });
});

describe('naturalCubicCoefficients', () => {
  it('gives a, b, c, d of each segment for ys = [0, 1, 0]', () => {
    // D = [3/2, 0, −3/2]: segment 0 is 0 + 1.5t + 0t² − 0.5t³, segment 1 is 1 + 0t − 1.5t² + 0.5t³.
    expect(naturalCubicCoefficients([0, 1, 0])).toEqual([
      [0, 1.5, 0, -0.5],
      [1, 0, -1.5, 0.5],
    ]);
  });
});

describe('batch natural spline', () => {
  it('matches naturalCubicDerivatives', () => {
    fc.assert(
      fc.property(values(1, 300), (ys) => {
        const batch = naturalCubicDerivativesBatch(Float64Array.from(ys));
        const reference = naturalCubicDerivatives(ys);
        reference.forEach((value, i) => expect(Math.abs(batch[i] - value)).toBeLessThan(1e-12));
      }),
    );
  });

  it('gives the control points of cubicSplineC2', () => {
    fc.assert(
      fc.property(polygon(1, 100), (points) => {
        const dimension = points[0].length;
        const coordinates = Array.from({ length: dimension }, (_, d) =>
          Float64Array.from(points, (p) => p[d]),
        );
        const { firstControl, secondControl } = naturalCubicBezierBatch(coordinates);
        const segments = cubicSplineC2(points);
        expect(firstControl[0]).toHaveLength(segments.length);
        segments.forEach((segment, i) => {
          expectClose(
            firstControl.map((c) => c[i]),
            segment[1],
            1e-12,
          );
          expectClose(
            secondControl.map((c) => c[i]),
            segment[2],
            1e-12,
          );
        });
      }),
    );
  });

  it('handles a million points', () => {
    const n = 1_000_000;
    const xs = Float64Array.from({ length: n }, (_, i) => i);
    const ys = Float64Array.from({ length: n }, (_, i) => Math.sin(i / 100));
    const { firstControl } = naturalCubicBezierBatch([xs, ys]);
    // Along a straight x the gradient is 1 everywhere, so B = x + 1/3.
    expect(firstControl[0][n / 2]).toBeCloseTo(n / 2 + 1 / 3, 9);
    expect(Number.isFinite(firstControl[1][n - 2])).toBe(true);
  });

  it('names a NaN or Infinity in its input', () => {
    const ys = Float64Array.of(0, 1, NaN, 3);
    expect(() => naturalCubicDerivativesBatch(ys)).toThrow(/values\[2\] is NaN/);
    expect(() =>
      naturalCubicBezierBatch([Float64Array.of(0, 1, 2), Float64Array.of(0, Infinity, 1)]),
    ).toThrow(/coordinates\[1\]\[1\] is Infinity/);
    expect(() => naturalCubicBezierBatch([Float64Array.of(0, 1), Float64Array.of(0)])).toThrow(
      /coordinates\[1\] has 1 values but coordinates\[0\] has 2/,
    );
    expect(() => naturalCubicDerivativesBatch(new Float64Array(0))).toThrow(RangeError);
    expect(() => naturalCubicDerivativesBatch(ys, ys)).toThrow(/separate Float64Array/);
  });
});

describe('d3-shape curveNatural as an outside reference', () => {
  const recordNatural = (points: readonly Point[]) => recordD3Bezier(curveNatural, points);

  const cases: Point[][] = [
    [
      [0, 0],
      [1, 1],
      [2, 0],
    ],
    [
      [0, 0],
      [1, 2],
      [3, 1],
      [4, 4],
      [6, 0],
    ],
    [
      [10, 10],
      [10, 10],
      [20, 5],
      [30, 30],
    ],
    Array.from({ length: 50 }, (_, i) => [i, Math.sin(i / 3) * 40]),
    Array.from({ length: 20 }, (_, i) => [1e6 + Math.cos(i), 1e6 + Math.sin(i)]),
  ];

  it('produces the same Bézier control points', () => {
    for (const points of cases) {
      const reference = recordNatural(points);
      const segments = cubicSplineC2(points);
      expect(segments).toHaveLength(reference.length);
      segments.forEach((segment, i) => {
        const [x1, y1, x2, y2, x, y] = reference[i];
        expectClose(segment[1], [x1, y1], 1e-9);
        expectClose(segment[2], [x2, y2], 1e-9);
        expectClose(segment[3], [x, y], 1e-12);
      });
    }
  });

  it('agrees on random point sets', () => {
    fc.assert(
      fc.property(fc.array(point(2), { minLength: 3, maxLength: 40 }), (points) => {
        const reference = recordNatural(points);
        cubicSplineC2(points).forEach((segment, i) => {
          expectClose(segment[1], reference[i].slice(0, 2), 1e-9);
          expectClose(segment[2], reference[i].slice(2, 4), 1e-9);
        });
      }),
    );
  });
});

describe('sampleNaturalCubicSpline', () => {
  it('passes through every point and matches cubicSplinePoint between', () => {
    const points: Point[] = [
      [0, 0],
      [1, 2],
      [3, 1],
    ];
    const samples = sampleNaturalCubicSpline(points, 4);
    expect(samples).toHaveLength((2 * 4 + 1) * 2);
    expect(Array.from(samples.subarray(8, 10))).toEqual([1, 2]);
    expect(Array.from(samples.subarray(16, 18))).toEqual([3, 1]);
    expectClose(
      Array.from(samples.subarray(2, 4)),
      cubicSplinePoint(points, naturalCubicTangents(points), 0.25),
    );
  });
});

describe('batch output buffers', () => {
  it('are reused when given, and checked', () => {
    const xs = Float64Array.of(0, 1, 2, 3);
    const ys = Float64Array.of(0, 1, 0, 1);
    const out = naturalCubicBezierBatch([xs, ys]);
    const again = naturalCubicBezierBatch([xs, ys], out);
    expect(again).toBe(out);
    expect(again.firstControl[1][0]).toBeCloseTo(5 / 9, 14);
    expect(() =>
      naturalCubicBezierBatch([xs, ys], { firstControl: [new Float64Array(3)], secondControl: [] }),
    ).toThrow(/out must hold 2 Float64Arrays/);
  });
});
