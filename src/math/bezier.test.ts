import { Bezier } from 'bezier-js';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, polygon, polygon2D, unitParameter } from './arbitraries.test-helpers';
import {
  bezierDerivative,
  bezierPoint,
  deCasteljau,
  elevateDegree,
  sampleBezier,
  splitBezier,
} from './bezier';
import type { Point } from './vec';

const lectureCubic: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

describe('deCasteljau', () => {
  it('builds every level of the construction at t = 1/2', () => {
    expect(deCasteljau(lectureCubic, 0.5)).toEqual([
      lectureCubic,
      [
        [0.5, 1],
        [2, 2],
        [3.5, 1],
      ],
      [
        [1.25, 1.5],
        [2.75, 1.5],
      ],
      [[2, 1.5]],
    ]);
  });

  it('copies the control points instead of sharing them', () => {
    const levels = deCasteljau(lectureCubic, 0.3);
    expect(levels[0][1]).not.toBe(lectureCubic[1]);
  });

  it('ends in the same point as bezierPoint', () => {
    fc.assert(
      fc.property(polygon(1, 8), unitParameter, (points, t) => {
        const levels = deCasteljau(points, t);
        expect(levels).toHaveLength(points.length);
        expect(levels[points.length - 1][0]).toEqual(bezierPoint(points, t));
      }),
    );
  });
});

describe('bezierPoint', () => {
  it('weights the cubic by 1/8, 3/8, 3/8, 1/8 at t = 1/2', () => {
    const [x0, x1, x2, x3] = [2, 7, -3, 5];
    const expected = x0 / 8 + (3 * x1) / 8 + (3 * x2) / 8 + x3 / 8;
    expect(bezierPoint([[x0], [x1], [x2], [x3]], 0.5)[0]).toBeCloseTo(expected, 14);
  });

  it('interpolates the end points exactly', () => {
    fc.assert(
      fc.property(polygon(1, 8), (points) => {
        expect(bezierPoint(points, 0)).toEqual(points[0]);
        expect(bezierPoint(points, 1)).toEqual(points[points.length - 1]);
      }),
    );
  });

  it('handles degree 0 and degree 1', () => {
    expect(bezierPoint([[3, 4, 5]], 0.7)).toEqual([3, 4, 5]);
    expectClose(
      bezierPoint(
        [
          [0, 0],
          [10, 20],
        ],
        0.25,
      ),
      [2.5, 5],
    );
  });

  it('is affine invariant: transforming the control points transforms the curve', () => {
    const matrix = fc.array(fc.double({ min: -3, max: 3, noNaN: true }), {
      minLength: 6,
      maxLength: 6,
    });
    fc.assert(
      fc.property(polygon2D(1, 7), matrix, unitParameter, (points, [a, b, c, d, e, f], t) => {
        const transform = (p: Point): Point => [a * p[0] + b * p[1] + e, c * p[0] + d * p[1] + f];
        expectClose(bezierPoint(points.map(transform), t), transform(bezierPoint(points, t)), 1e-8);
      }),
    );
  });

  it('stays inside the bounding box of its control points (convex hull property)', () => {
    fc.assert(
      fc.property(polygon(1, 8), unitParameter, (points, t) => {
        const p = bezierPoint(points, t);
        for (let d = 0; d < p.length; d++) {
          const values = points.map((q) => q[d]);
          expect(p[d]).toBeGreaterThanOrEqual(Math.min(...values) - 1e-9);
          expect(p[d]).toBeLessThanOrEqual(Math.max(...values) + 1e-9);
        }
      }),
    );
  });

  it('keeps full precision for coordinates near 1e6 and near 1e-6', () => {
    const offset = 1e6;
    const shifted = lectureCubic.map(([x, y]) => [x + offset, y + offset]);
    const p = bezierPoint(shifted, 0.5);
    expect(Math.abs(p[0] - (offset + 2))).toBeLessThan(1e-9);
    expect(Math.abs(p[1] - (offset + 1.5))).toBeLessThan(1e-9);
    const tiny = lectureCubic.map(([x, y]) => [x * 1e-6, y * 1e-6]);
    const q = bezierPoint(tiny, 0.5);
    expect(q[0]).toBeCloseTo(2e-6, 20);
    expect(Math.abs(q[1] / 1.5e-6 - 1)).toBeLessThan(1e-15);
  });

  it('agrees with bezier-js for quadratics and cubics', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 3, max: 4 }).chain((n) => polygon2D(n, n)),
        unitParameter,
        (points, t) => {
          const reference = new Bezier(points.map(([x, y]) => ({ x, y }))).compute(t);
          expectClose(bezierPoint(points, t), [reference.x, reference.y], 1e-9);
        },
      ),
    );
  });

  it('agrees with bezier-js in 3D', () => {
    fc.assert(
      fc.property(
        fc.array(point(3), { minLength: 4, maxLength: 4 }),
        unitParameter,
        (points, t) => {
          const reference = new Bezier(points.map(([x, y, z]) => ({ x, y, z }))).compute(t);
          expectClose(bezierPoint(points, t), [reference.x, reference.y, reference.z ?? NaN], 1e-9);
        },
      ),
    );
  });
});

describe('splitBezier', () => {
  it('takes the outer edges of the de Casteljau triangle', () => {
    const [left, right] = splitBezier(lectureCubic, 0.5);
    expect(left).toEqual([
      [0, 0],
      [0.5, 1],
      [1.25, 1.5],
      [2, 1.5],
    ]);
    expect(right).toEqual([
      [2, 1.5],
      [2.75, 1.5],
      [3.5, 1],
      [4, 0],
    ]);
  });

  it('reproduces the curve: left(u) = P(t·u), right(u) = P(t + (1 − t)·u)', () => {
    fc.assert(
      fc.property(polygon(1, 7), unitParameter, unitParameter, (points, t, u) => {
        const [left, right] = splitBezier(points, t);
        expectClose(bezierPoint(left, u), bezierPoint(points, t * u), 1e-8);
        expectClose(bezierPoint(right, u), bezierPoint(points, t + (1 - t) * u), 1e-8);
      }),
    );
  });

  it('agrees with bezier-js', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 3, max: 4 }).chain((n) => polygon2D(n, n)),
        fc.double({ min: 0.01, max: 0.99, noNaN: true }),
        (points, t) => {
          const reference = new Bezier(points.map(([x, y]) => ({ x, y }))).split(t);
          const [left, right] = splitBezier(points, t);
          left.forEach((p, i) =>
            expectClose(p, [reference.left.points[i].x, reference.left.points[i].y]),
          );
          right.forEach((p, i) =>
            expectClose(p, [reference.right.points[i].x, reference.right.points[i].y]),
          );
        },
      ),
    );
  });
});

describe('bezierDerivative', () => {
  it('starts at P′(0) = 3(P1 − P0) for a cubic', () => {
    const hodograph = bezierDerivative(lectureCubic);
    expect(hodograph).toEqual([
      [3, 6],
      [6, 0],
      [3, -6],
    ]);
    expect(bezierPoint(hodograph, 0)).toEqual([3 * (1 - 0), 3 * (2 - 0)]);
  });

  it('gives one zero vector for a single point', () => {
    expect(bezierDerivative([[1, 2, 3]])).toEqual([[0, 0, 0]]);
  });

  it('agrees with bezier-js derivative', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 3, max: 4 }).chain((n) => polygon2D(n, n)),
        unitParameter,
        (points, t) => {
          const reference = new Bezier(points.map(([x, y]) => ({ x, y }))).derivative(t);
          expectClose(bezierPoint(bezierDerivative(points), t), [reference.x, reference.y], 1e-9);
        },
      ),
    );
  });

  it('matches a central difference of the curve', () => {
    fc.assert(
      fc.property(polygon(2, 6), fc.double({ min: 0.01, max: 0.99, noNaN: true }), (points, t) => {
        const h = 1e-6;
        const ahead = bezierPoint(points, t + h);
        const behind = bezierPoint(points, t - h);
        const difference = ahead.map((value, d) => (value - behind[d]) / (2 * h));
        expectClose(bezierPoint(bezierDerivative(points), t), difference, 1e-4);
      }),
    );
  });
});

describe('elevateDegree', () => {
  it('follows Q_i = i/(n+1)·P(i−1) + (1 − i/(n+1))·P_i', () => {
    expect(
      elevateDegree([
        [0, 0],
        [3, 3],
        [6, 0],
      ]),
    ).toEqual([
      [0, 0],
      [2, 2],
      [4, 2],
      [6, 0],
    ]);
    expect(elevateDegree([[5, 5]])).toEqual([
      [5, 5],
      [5, 5],
    ]);
  });

  it('does not change the curve', () => {
    fc.assert(
      fc.property(polygon(1, 7), unitParameter, (points, t) => {
        const elevated = elevateDegree(points);
        expect(elevated).toHaveLength(points.length + 1);
        expectClose(bezierPoint(elevated, t), bezierPoint(points, t), 1e-8);
      }),
    );
  });
});

describe('sampleBezier', () => {
  it('matches bezierPoint at uniform parameters, exact at the ends', () => {
    fc.assert(
      fc.property(polygon(1, 6), fc.integer({ min: 1, max: 20 }), (points, segments) => {
        const dimension = points[0].length;
        const samples = sampleBezier(points, segments);
        expect(samples).toHaveLength((segments + 1) * dimension);
        for (let i = 0; i <= segments; i++) {
          const sample = Array.from(samples.subarray(i * dimension, (i + 1) * dimension));
          expectClose(sample, bezierPoint(points, i / segments), 1e-9);
        }
        expect(Array.from(samples.subarray(0, dimension))).toEqual(points[0]);
        expect(Array.from(samples.subarray(segments * dimension))).toEqual(
          points[points.length - 1],
        );
      }),
    );
  });

  it('reuses a buffer that is large enough', () => {
    const buffer = new Float64Array(100);
    expect(sampleBezier(lectureCubic, 10, buffer)).toBe(buffer);
  });
});

describe('bezierPoint on 2D and 3D cubics (its straight-line paths)', () => {
  const cubic = (dimension: number) => fc.array(point(dimension), { minLength: 4, maxLength: 4 });

  it('gives exactly de Casteljau’s point, in 2D and 3D', () => {
    fc.assert(
      fc.property(fc.oneof(cubic(2), cubic(3)), unitParameter, (points, t) => {
        const result = bezierPoint(points, t);
        expect(result).toEqual(deCasteljau(points, t)[3][0]);
        expect(Array.isArray(result)).toBe(true);
        expect(result).not.toBe(points[0]);
      }),
    );
  });

  it('agrees with the general loop of any other degree or dimension to 1e-12', () => {
    // Raising the degree keeps the curve but sends it down the general path.
    fc.assert(
      fc.property(fc.oneof(cubic(2), cubic(3)), unitParameter, (points, t) => {
        expectClose(bezierPoint(points, t), bezierPoint(elevateDegree(points), t), 1e-12);
        const lifted = points.map((p) => [...p, 0, 0]);
        expectClose(
          bezierPoint(lifted, t).slice(0, points[0].length),
          bezierPoint(points, t),
          1e-12,
        );
      }),
    );
  });

  it('still rejects anything wrong in a cubic, in words', () => {
    const withCoordinate = (value: unknown, dimension: number) =>
      lectureCubic.map((p, i) =>
        i === 2 ? [value, ...p.slice(1), 0].slice(0, dimension) : [...p, 0].slice(0, dimension),
      ) as Point[];
    for (const dimension of [2, 3]) {
      for (const [value, described] of [
        [NaN, 'NaN'],
        [Infinity, 'Infinity'],
        [null, 'null'],
        ['1', 'a string'],
        [undefined, 'undefined'],
        [[1], 'an array'],
      ] as const) {
        expect(() => bezierPoint(withCoordinate(value, dimension), 0.5)).toThrow(
          `bezierPoint: points[2][0] is ${described}; every coordinate must be a finite number.`,
        );
      }
    }
    expect(() => bezierPoint(lectureCubic, '0.5' as unknown as number)).toThrow(
      'bezierPoint: t = a string is outside the allowed range [0, 1].',
    );
    const mixed = [...lectureCubic.slice(0, 3), [4, 0, 0]];
    expect(() => bezierPoint(mixed, 0.5)).toThrow(/points\[3\] has 3 coordinates/);
    const notArray = [...lectureCubic.slice(0, 3), { 0: 4, 1: 0, length: 2 }] as unknown as Point[];
    expect(() => bezierPoint(notArray, 0.5)).toThrow(/points\[3\] is an? object/);
  });
});

describe('bad input', () => {
  const functions = [
    (points: Point[], t: number) => deCasteljau(points, t),
    (points: Point[], t: number) => bezierPoint(points, t),
    (points: Point[], t: number) => splitBezier(points, t),
  ];

  it('rejects an empty control polygon', () => {
    for (const f of functions)
      expect(() => f([], 0.5)).toThrow(/needs at least 1 point, but got 0/);
    expect(() => bezierDerivative([])).toThrow(RangeError);
    expect(() => elevateDegree([])).toThrow(RangeError);
  });

  it('rejects mixed dimensions', () => {
    const mixed = [
      [0, 0],
      [1, 1, 1],
    ];
    for (const f of functions) {
      expect(() => f(mixed, 0.5)).toThrow(/points\[1\] has 3 coordinates but points\[0\] has 2/);
    }
    expect(() => bezierDerivative(mixed)).toThrow(RangeError);
    expect(() => elevateDegree(mixed)).toThrow(RangeError);
  });

  it('rejects NaN and Infinity coordinates', () => {
    for (const bad of [NaN, Infinity, -Infinity]) {
      const points = [
        [0, 0],
        [1, bad],
      ];
      for (const f of functions)
        expect(() => f(points, 0.5)).toThrow(/points\[1\]\[1\] is .*finite number/);
    }
  });

  it('rejects a parameter outside [0, 1]', () => {
    for (const t of [-0.001, 1.001, NaN, Infinity]) {
      for (const f of functions)
        expect(() => f(lectureCubic, t)).toThrow(/t = .* is outside the allowed range/);
    }
  });

  it('rejects a point with no coordinates, or that is not an array', () => {
    expect(() => bezierPoint([[]], 0)).toThrow(/no coordinates/);
    expect(() => bezierPoint([null as unknown as Point], 0)).toThrow(/must be an array/);
  });

  it('never mutates its input', () => {
    const points = lectureCubic.map((p) => [...p]);
    const frozen = Object.freeze(points.map((p) => Object.freeze([...p])));
    deCasteljau(frozen, 0.3);
    splitBezier(frozen, 0.3);
    bezierDerivative(frozen);
    elevateDegree(frozen);
    bezierPoint(frozen, 0.3);
    expect(frozen).toEqual(points);
  });
});
