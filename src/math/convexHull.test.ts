import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { polygon2D, unitParameter } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { convexHull, convexHullContains } from './convexHull';
import type { Point } from './vec';

describe('convexHull', () => {
  it('keeps the corners anticlockwise from the lowest x, dropping inner and collinear points', () => {
    const points: Point[] = [
      [1, 1],
      [2, 0],
      [0, 0],
      [1, 0],
      [2, 2],
      [0, 2],
      [1, 2],
      [0.5, 1.5],
    ];
    expect(convexHull(points)).toEqual([
      [0, 0],
      [2, 0],
      [2, 2],
      [0, 2],
    ]);
  });

  it('handles one point, repeated points and a line', () => {
    expect(convexHull([[3, 4]])).toEqual([[3, 4]]);
    expect(
      convexHull([
        [3, 4],
        [3, 4],
        [3, 4],
      ]),
    ).toEqual([[3, 4]]);
    expect(
      convexHull([
        [0, 0],
        [1, 1],
        [2, 2],
        [0.5, 0.5],
      ]),
    ).toEqual([
      [0, 0],
      [2, 2],
    ]);
  });

  it('contains every input point and turns left at every corner', () => {
    // Small integers keep the turn test exact, so "strictly left" is checkable.
    const integerPoints = fc.array(
      fc.tuple(fc.integer({ min: -50, max: 50 }), fc.integer({ min: -50, max: 50 })),
      {
        minLength: 1,
        maxLength: 30,
      },
    );
    fc.assert(
      fc.property(integerPoints, (points) => {
        const hull = convexHull(points);
        points.forEach((p) => expect(convexHullContains(hull, p, 1e-9)).toBe(true));
        if (hull.length >= 3) {
          hull.forEach((a, i) => {
            const b = hull[(i + 1) % hull.length];
            const c = hull[(i + 2) % hull.length];
            expect((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).toBeGreaterThan(
              0,
            );
          });
        }
      }),
    );
  });

  it('rejects 3D points', () => {
    expect(() => convexHull([[0, 0, 0]])).toThrow(/3 coordinates but 2 are expected/);
  });
});

describe('convexHullContains', () => {
  const square = convexHull([
    [0, 0],
    [1, 0],
    [1, 1],
    [0, 1],
  ]);

  it('tells inside, boundary and outside apart', () => {
    expect(convexHullContains(square, [0.5, 0.5])).toBe(true);
    expect(convexHullContains(square, [1, 0.5])).toBe(true);
    expect(convexHullContains(square, [1.01, 0.5])).toBe(false);
    expect(convexHullContains(square, [1.01, 0.5], 0.02)).toBe(true);
    expect(
      convexHullContains(
        [
          [0, 0],
          [2, 0],
        ],
        [1, 0],
      ),
    ).toBe(true);
    expect(
      convexHullContains(
        [
          [0, 0],
          [2, 0],
        ],
        [1, 0.1],
      ),
    ).toBe(false);
    expect(convexHullContains([[0, 0]], [0, 0])).toBe(true);
  });
});

describe('the convex hull property of Bézier curves', () => {
  it('every curve point lies in the hull of the control points', () => {
    fc.assert(
      fc.property(polygon2D(1, 8), unitParameter, (points, t) => {
        const scale = Math.max(1, ...points.flat().map(Math.abs));
        expect(convexHullContains(convexHull(points), bezierPoint(points, t), 1e-9 * scale)).toBe(
          true,
        );
      }),
    );
  });
});
