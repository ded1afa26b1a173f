import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, unitParameter } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { bsplineBasis, clampedUniformKnots } from './bsplineBasis';
import { nurbsCircle, nurbsPoint } from './nurbs';
import type { Point } from './vec';

describe('nurbsPoint', () => {
  it('with unit weights equals the B-spline Σ Pi N(i,p)(t)', () => {
    fc.assert(
      fc.property(
        fc
          .integer({ min: 0, max: 4 })
          .chain((degree) =>
            fc.tuple(
              fc.constant(degree),
              fc.array(point(2), { minLength: degree + 1, maxLength: degree + 8 }),
            ),
          ),
        unitParameter,
        ([degree, points], t) => {
          const knots = clampedUniformKnots(points.length, degree);
          const expected = [0, 0];
          points.forEach((p, i) => {
            const weight = bsplineBasis(knots, degree, i, t);
            expected[0] += weight * p[0];
            expected[1] += weight * p[1];
          });
          expectClose(
            nurbsPoint(points, new Array(points.length).fill(1), knots, degree, t),
            expected,
            1e-9,
          );
        },
      ),
    );
  });

  it('with a clamped vector and one span is the Bézier curve', () => {
    fc.assert(
      fc.property(
        fc.array(point(3), { minLength: 4, maxLength: 4 }),
        unitParameter,
        (points, t) => {
          expectClose(
            nurbsPoint(points, [1, 1, 1, 1], [0, 0, 0, 0, 1, 1, 1, 1], 3, t),
            bezierPoint(points, t),
            1e-9,
          );
        },
      ),
    );
  });

  it('draws an exact circle with the 9-point quadratic', () => {
    const { points, weights, knots, degree } = nurbsCircle([2, -1], 3);
    fc.assert(
      fc.property(unitParameter, (t) => {
        const [x, y] = nurbsPoint(points, weights, knots, degree, t);
        expect(Math.hypot(x - 2, y + 1)).toBeCloseTo(3, 12);
      }),
    );
    expectClose(nurbsPoint(points, weights, knots, degree, 0.25), [2, 2]);
    expectClose(nurbsPoint(points, weights, knots, degree, 1), [5, -1]);
  });

  it('is pulled towards a control point as its weight grows', () => {
    const points: Point[] = [
      [0, 0],
      [1, 2],
      [2, 0],
    ];
    const knots = [0, 0, 0, 1, 1, 1];
    const light = nurbsPoint(points, [1, 1, 1], knots, 2, 0.5);
    const heavy = nurbsPoint(points, [1, 5, 1], knots, 2, 0.5);
    expect(heavy[1]).toBeGreaterThan(light[1]);
  });

  it('rejects mismatched knots or weights, negative weights and t out of range', () => {
    const points: Point[] = [
      [0, 0],
      [1, 1],
      [2, 0],
    ];
    expect(() => nurbsPoint(points, [1, 1, 1], [0, 0, 1, 1], 2, 0.5)).toThrow(
      /knots has 4 entries but 3 points of degree 2 need/,
    );
    expect(() => nurbsPoint(points, [1, 1], [0, 0, 0, 1, 1, 1], 2, 0.5)).toThrow(
      /weights has 2 entries but points has 3/,
    );
    expect(() => nurbsPoint(points, [1, -1, 1], [0, 0, 0, 1, 1, 1], 2, 0.5)).toThrow(
      /weights\[1\] = -1 is negative/,
    );
    expect(() => nurbsPoint(points, [0, 0, 0], [0, 0, 0, 1, 1, 1], 2, 0.5)).toThrow(/weight 0/);
    expect(() => nurbsPoint(points, [1, 1, 1], [0, 0, 0, 1, 1, 1], 2, 1.5)).toThrow(
      /t = 1.5 is outside/,
    );
  });
});
