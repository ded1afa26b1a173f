import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, polygon } from './arbitraries.test-helpers';
import { bezierDerivative, bezierPoint } from './bezier';
import { bezierSplinePoint, cubicSplineC2, quadraticSplineC1 } from './bezierSpline';
import { naturalCubicDerivatives } from './naturalCubic';
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

describe('cubicSplineC2 from the gradients', () => {
  it('has Bi = Pi + Di/3 and Ci = P(i+1) − D(i+1)/3 with naturalCubicDerivatives per coordinate', () => {
    // 1D and 4D take the general path, 2D and 3D their own.
    const points = fc
      .integer({ min: 1, max: 4 })
      .chain((dimension) => fc.array(point(dimension), { minLength: 1, maxLength: 40 }));
    fc.assert(
      fc.property(points, (points) => {
        const dimension = points[0].length;
        const gradients = Array.from({ length: dimension }, (_, d) =>
          naturalCubicDerivatives(points.map((p) => p[d])),
        );
        const segments = cubicSplineC2(points);
        expect(segments).toHaveLength(points.length - 1);
        segments.forEach((segment, i) => {
          expect(segment).toHaveLength(4);
          expect(segment[0]).toEqual(points[i]);
          expect(segment[3]).toEqual(points[i + 1]);
          expect(segment[0]).not.toBe(points[i]);
          expect(segment[3]).not.toBe(points[i + 1]);
          const first = points[i].map((value, d) => value + gradients[d][i] / 3);
          const second = points[i + 1].map((value, d) => value - gradients[d][i + 1] / 3);
          expectClose(segment[1], first, 1e-12);
          expectClose(segment[2], second, 1e-12);
        });
      }),
    );
  });

  it('returns fresh arrays and leaves its input alone', () => {
    const points: Point[] = [
      [0, 0, 1],
      [1, 2, 3],
      [4, 1, 0],
    ];
    const copy = structuredClone(points);
    const segments = cubicSplineC2(points);
    expect(points).toEqual(copy);
    expect(segments[0][3]).not.toBe(segments[1][0]);
    expect(segments[0][3]).toEqual(segments[1][0]);
  });

  it('rejects bad points with a RangeError that names it, and points that overflow', () => {
    const bad = (points: unknown) => () => cubicSplineC2(points as Point[]);
    expect(bad([])).toThrow('cubicSplineC2: points needs at least 1 point, but got 0.');
    expect(bad([[0, 0], [1]])).toThrow(/^cubicSplineC2: points\[1\] has 1 coordinates/);
    expect(
      bad([
        [0, 0],
        [1, NaN],
      ]),
    ).toThrow(/^cubicSplineC2: points\[1\]\[1\] is NaN/);
    expect(
      bad([
        [0, 0],
        [1, '2'],
      ]),
    ).toThrow(/^cubicSplineC2: points\[1\]\[1\] is a string/);
    expect(bad([[0, 0], null])).toThrow(/^cubicSplineC2: points\[1\] is null/);
    expect(bad('points')).toThrow(/^cubicSplineC2: points is a string/);
    expect(
      bad([
        [0, -1e308],
        [1, 1e308],
        [2, -1e308],
      ]),
    ).toThrow(/^cubicSplineC2: points holds values so large that the result overflows/);
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
