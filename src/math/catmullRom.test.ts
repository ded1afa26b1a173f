import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, polygon } from './arbitraries.test-helpers';
import { bezierDerivative, bezierPoint } from './bezier';
import { catmullRomPoint, catmullRomSegments, catmullRomTangents } from './catmullRom';
import { cubicSplinePoint } from './cubicSpline';
import type { Point } from './vec';

const points: Point[] = [
  [0, 0],
  [1, 2],
  [4, 2],
  [5, 0],
];

describe('catmullRomTangents', () => {
  it('is (P(i+1) − P(i−1))/2 inside and zero at the ends', () => {
    expect(catmullRomTangents(points)).toEqual([
      [0, 0],
      [2, 1],
      [2, -1],
      [0, 0],
    ]);
    expect(catmullRomTangents([[1, 2, 3]])).toEqual([[0, 0, 0]]);
  });
});

describe('catmullRomSegments', () => {
  it('with alpha = 0 draws the curve of catmullRomTangents', () => {
    fc.assert(
      fc.property(polygon(2, 10), fc.double({ min: 0, max: 1, noNaN: true }), (ps, t) => {
        const segments = catmullRomSegments(ps, 0);
        const tangents = catmullRomTangents(ps);
        segments.forEach((segment, i) =>
          expectClose(bezierPoint(segment, t), cubicSplinePoint(ps, tangents, i + t), 1e-8),
        );
      }),
    );
  });

  it('interpolates every point and is G1 (tangent directions agree) at joints', () => {
    fc.assert(
      fc.property(polygon(3, 10), fc.constantFrom(0, 0.5, 1), (ps, alpha) => {
        const segments = catmullRomSegments(ps, alpha);
        segments.forEach((segment, i) => {
          expect(segment[0]).toEqual(ps[i]);
          expect(segment[3]).toEqual(ps[i + 1]);
          if (i === 0) return;
          const incoming = bezierPoint(bezierDerivative(segments[i - 1]), 1);
          const outgoing = bezierPoint(bezierDerivative(segment), 0);
          // Parallel and pointing the same way: cross product ≈ 0, dot ≥ 0.
          const [a, b] = [incoming, outgoing];
          const dot = a.reduce((sum, value, d) => sum + value * b[d], 0);
          const sizes = Math.hypot(...a) * Math.hypot(...b);
          expect(dot).toBeGreaterThanOrEqual(-1e-9 * Math.max(1, sizes));
          expect(Math.abs(sizes - dot)).toBeLessThanOrEqual(1e-6 * Math.max(1, sizes));
        });
      }),
    );
  });

  it('centripetal: knot gaps √|ΔP| scale the tangents of each segment', () => {
    // Uniform spacing makes every knot gap equal, so alpha does not matter.
    const even: Point[] = [
      [0, 0],
      [1, 0],
      [2, 0],
      [3, 0],
    ];
    const uniform = catmullRomSegments(even, 0);
    const centripetal = catmullRomSegments(even, 0.5);
    centripetal.forEach((segment, i) => segment.forEach((p, j) => expectClose(p, uniform[i][j])));
  });

  it('does not divide by zero at repeated points', () => {
    const repeated: Point[] = [
      [0, 0],
      [1, 1],
      [1, 1],
      [2, 0],
    ];
    for (const alpha of [0, 0.5, 1]) {
      expect(catmullRomSegments(repeated, alpha).flat(2).every(Number.isFinite)).toBe(true);
    }
  });

  it('rejects alpha outside [0, 1]', () => {
    expect(() => catmullRomSegments(points, 1.5)).toThrow(/alpha = 1.5 is outside/);
  });
});

describe('catmullRomPoint', () => {
  it('evaluates the segments at global s', () => {
    fc.assert(
      fc.property(
        polygon(2, 8),
        fc.constantFrom(0, 0.5, 1),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (ps, alpha, fraction) => {
          const m = ps.length - 1;
          const s = fraction * m;
          const i = Math.min(Math.floor(s), m - 1);
          expectClose(
            catmullRomPoint(ps, alpha, s),
            bezierPoint(catmullRomSegments(ps, alpha)[i], s - i),
            1e-8,
          );
        },
      ),
    );
    expect(catmullRomPoint([[3, 3]], 0.5, 0)).toEqual([3, 3]);
  });
});
