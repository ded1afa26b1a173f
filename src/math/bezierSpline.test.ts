import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, polygon } from './arbitraries.test-helpers';
import { bezierDerivative, bezierPoint } from './bezier';
import { bezierSplinePoint, cubicSplineC2, quadraticSplineC1 } from './bezierSpline';
import type { Point } from './vec';

const derivativeAt = (points: readonly Point[], t: number, order: number): Point => {
  let hodograph: readonly Point[] = points;
  for (let k = 0; k < order; k++) hodograph = bezierDerivative(hodograph);
  return bezierPoint(hodograph, t);
};

describe('quadraticSplineC1', () => {
  it('reflects each control point through the next joint', () => {
    expect(
      quadraticSplineC1(
        [
          [0, 0],
          [2, 0],
          [4, 0],
        ],
        [1, 1],
      ),
    ).toEqual([
      [
        [0, 0],
        [1, 1],
        [2, 0],
      ],
      [
        [2, 0],
        [3, -1],
        [4, 0],
      ],
    ]);
    expect(quadraticSplineC1([[1, 1]], [0, 0])).toEqual([]);
  });

  it('interpolates the points with C¹ continuity at every joint', () => {
    fc.assert(
      fc.property(
        polygon(1, 10).chain((points) => fc.tuple(fc.constant(points), point(points[0].length))),
        ([points, first]) => {
          const segments = quadraticSplineC1(points, first);
          expect(segments).toHaveLength(points.length - 1);
          segments.forEach((segment, i) => {
            expect(segment[0]).toEqual(points[i]);
            expect(segment[2]).toEqual(points[i + 1]);
            if (i > 0)
              expectClose(derivativeAt(segments[i - 1], 1, 1), derivativeAt(segment, 0, 1), 1e-9);
          });
        },
      ),
    );
  });
});

describe('cubicSplineC2', () => {
  it('interpolates with C² continuity and zero second derivative at both ends', () => {
    fc.assert(
      fc.property(polygon(2, 12), (points) => {
        const segments = cubicSplineC2(points);
        const m = points.length - 1;
        expect(segments).toHaveLength(m);
        segments.forEach((segment, i) => {
          expect(segment[0]).toEqual(points[i]);
          expect(segment[3]).toEqual(points[i + 1]);
          if (i > 0) {
            expectClose(derivativeAt(segments[i - 1], 1, 1), derivativeAt(segment, 0, 1), 1e-8);
            expectClose(derivativeAt(segments[i - 1], 1, 2), derivativeAt(segment, 0, 2), 1e-7);
          }
        });
        const zero = new Array<number>(points[0].length).fill(0);
        expectClose(derivativeAt(segments[0], 0, 2), zero, 1e-7);
        expectClose(derivativeAt(segments[m - 1], 1, 2), zero, 1e-7);
      }),
    );
  });

  it('draws a straight segment through two points', () => {
    const [segment] = cubicSplineC2([
      [0, 0],
      [3, 3],
    ]);
    expectClose(segment[1], [1, 1]);
    expectClose(segment[2], [2, 2]);
  });

  it('handles repeated and collinear points', () => {
    const segments = cubicSplineC2([
      [0, 0],
      [0, 0],
      [1, 1],
      [2, 2],
    ]);
    expect(segments.flat().flat().every(Number.isFinite)).toBe(true);
    expect(cubicSplineC2([[4, 5, 6]])).toEqual([]);
  });
});

describe('bezierSplinePoint', () => {
  it('evaluates segment floor(s) at s − i', () => {
    const segments = cubicSplineC2([
      [0, 0],
      [1, 1],
      [2, 0],
    ]);
    expectClose(bezierSplinePoint(segments, 1.25), bezierPoint(segments[1], 0.25));
    expect(bezierSplinePoint(segments, 2)).toEqual([2, 0]);
    expect(() => bezierSplinePoint(segments, 2.5)).toThrow(/s = 2.5 is outside/);
    expect(() => bezierSplinePoint([], 0)).toThrow(/at least 1 segment/);
  });
});
