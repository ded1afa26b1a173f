import { curveBasis } from 'd3-shape';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, polygon, unitParameter } from './arbitraries.test-helpers';
import { bezierDerivative, bezierPoint } from './bezier';
import { bsplineBasis, uniformKnots } from './bsplineBasis';
import {
  bezierToUniformBSpline,
  uniformBSplineBasis,
  uniformBSplineMatrix,
  uniformBSplinePoint,
  uniformBSplineSegments,
  uniformBSplineToBezier,
} from './uniformBSpline';
import { sampleUniformBSpline, uniformBSplineBezierBatch } from './uniformBSplineBatch';
import type { Point } from './vec';
import { recordD3Bezier } from './d3Reference.test-helpers';

describe('uniformBSplineMatrix', () => {
  it('is the lecture’s (1/6)[[1,4,1,0],[−3,0,3,0],[3,−6,3,0],[−1,3,−3,1]]', () => {
    const sixTimes = uniformBSplineMatrix().map((row) => row.map((value) => Math.round(6 * value)));
    expect(sixTimes).toEqual([
      [1, 4, 1, 0],
      [-3, 0, 3, 0],
      [3, -6, 3, 0],
      [-1, 3, -3, 1],
    ]);
  });

  it('gives the same blending functions as uniformBSplineBasis', () => {
    fc.assert(
      fc.property(unitParameter, (t) => {
        const matrix = uniformBSplineMatrix();
        const monomials = [1, t, t * t, t * t * t];
        const expected = [0, 1, 2, 3].map((j) =>
          monomials.reduce((sum, value, k) => sum + value * matrix[k][j], 0),
        );
        uniformBSplineBasis(t).forEach((value, j) => expect(value).toBeCloseTo(expected[j], 14));
      }),
    );
  });
});

describe('uniformBSplineBasis', () => {
  it('starts at (1/6, 4/6, 1/6, 0) and ends at (0, 1/6, 4/6, 1/6)', () => {
    expect(uniformBSplineBasis(0)).toEqual([1 / 6, 4 / 6, 1 / 6, 0]);
    expect(uniformBSplineBasis(1)).toEqual([0, 1 / 6, 4 / 6, 1 / 6]);
  });

  it('is a non-negative partition of unity', () => {
    fc.assert(
      fc.property(unitParameter, (t) => {
        const values = uniformBSplineBasis(t);
        values.forEach((value) => expect(value).toBeGreaterThanOrEqual(0));
        expect(values.reduce((a, b) => a + b, 0)).toBeCloseTo(1, 14);
      }),
    );
  });

  it('agrees with Cox–de Boor on uniform knots', () => {
    const knots = uniformKnots(4, 3);
    fc.assert(
      fc.property(unitParameter, (t) => {
        const values = uniformBSplineBasis(t);
        // On knots 0…7 the segment blending P0…P3 lives on [3, 4].
        values.forEach((value, j) =>
          expect(bsplineBasis(knots, 3, j, 3 + t)).toBeCloseTo(value, 14),
        );
      }),
    );
  });
});

describe('uniformBSplinePoint', () => {
  it('starts at (P0 + 4P1 + P2)/6 and ends at (P(m−2) + 4P(m−1) + Pm)/6', () => {
    const points: Point[] = [
      [0, 0],
      [6, 0],
      [6, 6],
      [0, 6],
      [0, 12],
    ];
    expectClose(uniformBSplinePoint(points, 0), [5, 1]);
    expectClose(uniformBSplinePoint(points, 2), [1, 7]);
  });

  it('is C² across segment joints', () => {
    fc.assert(
      fc.property(polygon(5, 10), (points) => {
        const segments = uniformBSplineSegments(points);
        for (let i = 1; i < segments.length; i++) {
          let [a, b] = [segments[i - 1], segments[i]];
          for (let order = 0; order <= 2; order++) {
            expectClose(bezierPoint(a, 1), bezierPoint(b, 0), 1e-7);
            [a, b] = [bezierDerivative(a), bezierDerivative(b)];
          }
        }
      }),
    );
  });

  it('lies in the convex hull (bounding box) of the four control points of its segment', () => {
    fc.assert(
      fc.property(polygon(4, 10), unitParameter, (points, fraction) => {
        const s = fraction * (points.length - 3);
        const i = Math.min(Math.floor(s), points.length - 4);
        const p = uniformBSplinePoint(points, s);
        for (let d = 0; d < p.length; d++) {
          const values = points.slice(i, i + 4).map((q) => q[d]);
          expect(p[d]).toBeGreaterThanOrEqual(Math.min(...values) - 1e-9);
          expect(p[d]).toBeLessThanOrEqual(Math.max(...values) + 1e-9);
        }
      }),
    );
  });

  it('rejects fewer than four points and s outside [0, m − 2]', () => {
    expect(() => uniformBSplinePoint([[0], [1], [2]], 0)).toThrow(/at least 4 points, but got 3/);
    expect(() => uniformBSplinePoint([[0], [1], [2], [3]], 1.5)).toThrow(
      /s = 1.5 is outside the allowed range \[0, 1\]/,
    );
  });
});

describe('Bézier ↔ uniform B-spline conversion', () => {
  it('converts the segment control points both ways', () => {
    const bspline: Point[] = [
      [0, 0],
      [6, 0],
      [6, 6],
      [0, 6],
    ];
    expect(uniformBSplineToBezier(bspline)).toEqual([
      [5, 1],
      [6, 2],
      [6, 4],
      [5, 5],
    ]);
    bezierToUniformBSpline(uniformBSplineToBezier(bspline)).forEach((p, i) =>
      expectClose(p, bspline[i], 1e-12),
    );
  });

  it('draws the same curve, and round-trips', () => {
    fc.assert(
      fc.property(
        fc.constantFrom(2, 3).chain((d) => fc.array(point(d), { minLength: 4, maxLength: 4 })),
        unitParameter,
        (points, t) => {
          expectClose(
            bezierPoint(uniformBSplineToBezier(points), t),
            uniformBSplinePoint(points, t),
            1e-9,
          );
          bezierToUniformBSpline(uniformBSplineToBezier(points)).forEach((p, i) =>
            expectClose(p, points[i], 1e-9),
          );
        },
      ),
    );
  });
});

describe('batch B-spline helpers', () => {
  const coordinatesOf = (points: readonly Point[]) =>
    points[0].map((_, d) => Float64Array.from(points, (p) => p[d]));

  it('sampleUniformBSpline matches uniformBSplinePoint', () => {
    fc.assert(
      fc.property(polygon(4, 20), fc.integer({ min: 1, max: 5 }), (points, k) => {
        const samples = sampleUniformBSpline(coordinatesOf(points), k);
        const segments = points.length - 3;
        expect(samples[0]).toHaveLength(segments * k + 1);
        for (let j = 0; j <= segments * k; j++) {
          expectClose(
            samples.map((c) => c[j]),
            uniformBSplinePoint(points, j / k),
            1e-9,
          );
        }
      }),
    );
  });

  it('uniformBSplineBezierBatch matches uniformBSplineSegments', () => {
    fc.assert(
      fc.property(polygon(4, 20), (points) => {
        const { joints, firstControl, secondControl } = uniformBSplineBezierBatch(
          coordinatesOf(points),
        );
        uniformBSplineSegments(points).forEach((segment, i) => {
          expectClose(
            joints.map((c) => c[i]),
            segment[0],
            1e-12,
          );
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
          expectClose(
            joints.map((c) => c[i + 1]),
            segment[3],
            1e-12,
          );
        });
      }),
    );
  });

  it('agrees with d3-shape curveBasis on the inner segments', () => {
    // d3 adds clamped end pieces; between them it draws the same uniform B-spline.
    const points: Point[] = Array.from({ length: 12 }, (_, i) => [i * 10, Math.sin(i) * 30]);
    const calls = recordD3Bezier(curveBasis, points);
    const segments = uniformBSplineSegments(points);
    // d3's first bezierCurveTo is its clamped start piece; then one per segment.
    segments.forEach((segment, i) => {
      const [x1, y1, x2, y2, x, y] = calls[i + 1];
      expectClose(segment[1], [x1, y1], 1e-12);
      expectClose(segment[2], [x2, y2], 1e-12);
      expectClose(segment[3], [x, y], 1e-12);
    });
  });

  it('name a NaN in their input', () => {
    const xs = Float64Array.of(0, 1, 2, 3, 4);
    const ys = Float64Array.of(0, 1, 2, NaN, 4);
    expect(() => sampleUniformBSpline([xs, ys], 3)).toThrow(/coordinates\[1\]\[3\] is NaN/);
    expect(() => uniformBSplineBezierBatch([xs, ys])).toThrow(/coordinates\[1\]\[3\] is NaN/);
    expect(() => uniformBSplineBezierBatch([xs.subarray(0, 3)])).toThrow(/at least 4 points/);
  });
});

describe('uniformBSplineBezierBatch output buffers', () => {
  it('are reused when given, and checked', () => {
    const xs = Float64Array.of(0, 6, 6, 0, 0);
    const out = uniformBSplineBezierBatch([xs]);
    expect(uniformBSplineBezierBatch([xs], out)).toBe(out);
    // Joints (P(i) + 4P(i+1) + P(i+2))/6: (0 + 24 + 6)/6, (6 + 24 + 0)/6, (6 + 0 + 0)/6.
    expect(Array.from(out.joints[0])).toEqual([5, 5, 1]);
    expect(() =>
      uniformBSplineBezierBatch([xs], {
        joints: [new Float64Array(1)],
        firstControl: [],
        secondControl: [],
      }),
    ).toThrow(/out must hold 1 Float64Arrays per field/);
  });
});

describe('sampleUniformBSpline output buffers', () => {
  it('are reused when given, and checked', () => {
    const xs = Float64Array.of(0, 6, 6, 0, 0);
    const out = sampleUniformBSpline([xs], 2);
    expect(out[0]).toHaveLength(5);
    expect(sampleUniformBSpline([xs], 2, out)).toBe(out);
    expect(() => sampleUniformBSpline([xs], 2, [new Float64Array(4)])).toThrow(
      /out must hold 1 Float64Arrays of at least 5 entries/,
    );
  });
});
