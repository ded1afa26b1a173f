import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, polygon } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import {
  closedCubicSplinePoint,
  cubicSplineCoefficients,
  cubicSplinePoint,
  cubicSplineSegments,
  sampleCubicSpline,
} from './cubicSpline';
import { hermitePoint } from './hermite';
import type { Point } from './vec';

const withTangents = (minimum: number) =>
  polygon(minimum * 2, 16).map((all) => {
    const half = Math.floor(all.length / 2);
    return { points: all.slice(0, half), tangents: all.slice(half, 2 * half) };
  });

describe('cubicSplinePoint', () => {
  it('maps global s to segment min(floor(s), m−1) and local t = s − i', () => {
    fc.assert(
      fc.property(
        withTangents(2),
        fc.double({ min: 0, max: 1, noNaN: true }),
        ({ points, tangents }, fraction) => {
          const m = points.length - 1;
          const s = fraction * m;
          const i = Math.min(Math.floor(s), m - 1);
          expectClose(
            cubicSplinePoint(points, tangents, s),
            hermitePoint(points[i], tangents[i], points[i + 1], tangents[i + 1], s - i),
            1e-9,
          );
        },
      ),
    );
  });

  it('passes exactly through every point', () => {
    fc.assert(
      fc.property(withTangents(1), ({ points, tangents }) => {
        points.forEach((p, i) => expect(cubicSplinePoint(points, tangents, i)).toEqual(p));
      }),
    );
  });

  it('draws a straight segment through two points with equal chord tangents', () => {
    const points: Point[] = [
      [0, 0],
      [3, 6],
    ];
    expectClose(
      cubicSplinePoint(
        points,
        [
          [3, 6],
          [3, 6],
        ],
        0.5,
      ),
      [1.5, 3],
    );
  });

  it('rejects s out of range and tangent count mismatch', () => {
    const points: Point[] = [
      [0, 0],
      [1, 1],
      [2, 0],
    ];
    const tangents: Point[] = [
      [1, 0],
      [1, 0],
      [1, 0],
    ];
    expect(() => cubicSplinePoint(points, tangents, 2.5)).toThrow(
      /s = 2.5 is outside the allowed range \[0, 2\]/,
    );
    expect(() => cubicSplinePoint(points, tangents.slice(0, 2), 1)).toThrow(
      /points has 3 entries but tangents has 2/,
    );
    expect(() => cubicSplinePoint([], [], 0)).toThrow(/at least 1 point/);
  });
});

describe('closedCubicSplinePoint', () => {
  it('adds the segment from the last point back to the first', () => {
    const points: Point[] = [
      [0, 0],
      [1, 0],
      [1, 1],
    ];
    const tangents: Point[] = [
      [1, -1],
      [1, 1],
      [-1, 0],
    ];
    expectClose(
      closedCubicSplinePoint(points, tangents, 2.5),
      hermitePoint(points[2], tangents[2], points[0], tangents[0], 0.5),
    );
    expect(closedCubicSplinePoint(points, tangents, 3)).toEqual(points[0]);
    expect(() => closedCubicSplinePoint(points, tangents, 3.1)).toThrow(/\[0, 3\]/);
  });
});

describe('cubicSplineSegments', () => {
  it('gives Bézier segments that draw the same curve', () => {
    fc.assert(
      fc.property(
        withTangents(2),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.boolean(),
        ({ points, tangents }, t, closed) => {
          const segments = cubicSplineSegments(points, tangents, closed);
          expect(segments).toHaveLength(closed ? points.length : points.length - 1);
          segments.forEach((segment, i) => {
            const s = i + t;
            const expected = closed
              ? closedCubicSplinePoint(points, tangents, s)
              : cubicSplinePoint(points, tangents, s);
            expectClose(bezierPoint(segment, t), expected, 1e-8);
          });
        },
      ),
    );
  });
});

describe('cubicSplineCoefficients', () => {
  it('gives a + bt + ct² + dt³ per segment from values and gradients', () => {
    // y0 = 1, y1 = 2, D0 = 0, D1 = 3: c = 3·1 − 0 − 3 = 0, d = 2·(−1) + 0 + 3 = 1.
    expect(cubicSplineCoefficients([1, 2], [0, 3])).toEqual([[1, 0, 0, 1]]);
    expect(cubicSplineCoefficients([5], [0])).toEqual([]);
    expect(() => cubicSplineCoefficients([1, 2], [0])).toThrow(/ys has 2 entries but ds has 1/);
  });
});

describe('sampleCubicSpline', () => {
  it('matches cubicSplinePoint at every sample', () => {
    fc.assert(
      fc.property(withTangents(1), fc.integer({ min: 1, max: 6 }), ({ points, tangents }, k) => {
        const dimension = points[0].length;
        const samples = sampleCubicSpline(points, tangents, k);
        const m = points.length - 1;
        expect(samples).toHaveLength((m * k + 1) * dimension);
        for (let j = 0; j <= m * k; j++) {
          expectClose(
            Array.from(samples.subarray(j * dimension, (j + 1) * dimension)),
            cubicSplinePoint(points, tangents, j / k),
            1e-9,
          );
        }
      }),
    );
  });
});
