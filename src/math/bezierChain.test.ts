import { describe, expect, it } from 'vitest';
import { elevateDegree } from './bezier';
import { bezierChainSegments, bezierInflections } from './bezierChain';
import { bezierCurvature } from './curvature';
import { catmullRomSegments } from './catmullRom';
import { cubicSplineC2 } from './bezierSpline';
import { uniformBSplineSegments } from './uniformBSpline';
import type { Point } from './vec';

const S_CURVE: Point[] = [
  [0, 0],
  [1.5, 2.5],
  [2.5, -2.5],
  [4, 0],
];

describe('bezierChainSegments', () => {
  it('splits 3k + 1 points into k cubics that share their joints', () => {
    const points: Point[] = Array.from({ length: 7 }, (_, i) => [i, i * i]);
    expect(bezierChainSegments(points, 3)).toEqual([points.slice(0, 4), points.slice(3, 7)]);
    expect(bezierChainSegments(points, 2)).toHaveLength(3);
    expect(bezierChainSegments(points, 6)).toEqual([points]);
  });

  it('refuses a count that does not fit the degree', () => {
    const five: Point[] = Array.from({ length: 5 }, (_, i) => [i, 0]);
    expect(() => bezierChainSegments(five, 3)).toThrow(/k·3 \+ 1/);
    expect(() => bezierChainSegments(five.slice(0, 1), 1)).toThrow(RangeError);
  });
});

describe('bezierInflections', () => {
  it('finds the S curve’s inflection at t = 1/2 at degree 3, and at degrees 4 and 5 (same curve)', () => {
    expect(bezierInflections(S_CURVE)).toEqual([0.5]);
    const quartic = elevateDegree(S_CURVE);
    const quintic = elevateDegree(quartic);
    for (const p of [quartic, quintic]) {
      const found = bezierInflections(p);
      expect(found).toHaveLength(1);
      expect(found[0]).toBeCloseTo(0.5, 12);
    }
  });

  it('finds none on a parabola, a line, or collinear points of high degree', () => {
    expect(
      bezierInflections([
        [0, 0],
        [1, 2],
        [2, 0],
      ]),
    ).toEqual([]);
    const straight: Point[] = Array.from({ length: 6 }, (_, i) => [i, 2 * i]);
    expect(bezierInflections(straight)).toEqual([]);
  });
});

// The conversions the curvature lesson draws any spline with: each source
// becomes a list of Bézier segments, checked against closed forms.
describe('splines as Bézier segments, by their curvature', () => {
  it('the natural cubic spline through collinear points is straight: κ ≡ 0', () => {
    const points: Point[] = [
      [0, 0],
      [1, 0.5],
      [3, 1.5],
      [3.5, 1.75],
      [6, 3],
    ];
    for (const segment of cubicSplineC2(points))
      for (const t of [0, 0.25, 0.5, 0.75, 1])
        expect(Math.abs(bezierCurvature(segment, t))).toBeLessThan(1e-12);
  });

  it('a uniform cubic B-spline has the same κ on both sides of every joint (C²)', () => {
    const points: Point[] = [
      [0, 0],
      [1, 3],
      [3, 3.5],
      [4, 0.5],
      [6, 1],
      [7, 4],
    ];
    const segments = uniformBSplineSegments(points);
    expect(segments).toHaveLength(3);
    for (let i = 0; i + 1 < segments.length; i++) {
      const left = bezierCurvature(segments[i], 1);
      const right = bezierCurvature(segments[i + 1], 0);
      expect(right).toBeCloseTo(left, 12);
    }
  });

  it('a Catmull-Rom spline through points on a circle of radius R has κ close to 1/R', () => {
    // Points θ apart on the circle: at a joint P′ = (P(i+1) − P(i−1))/2 has length
    // R sin θ and P″ = 6(P(i+1) − Pi) − 4Di − 2D(i+1), which gives by hand
    // κ = (6 − 6 cos θ − 2 sin²θ)/(R sin²θ) = (1 + O(θ²))/R.
    const R = 2;
    for (const degrees of [15, 5]) {
      const theta = (degrees * Math.PI) / 180;
      const points: Point[] = Array.from({ length: 360 / degrees + 1 }, (_, k) => [
        R * Math.cos(k * theta),
        R * Math.sin(k * theta),
      ]);
      const atJoint =
        (6 - 6 * Math.cos(theta) - 2 * Math.sin(theta) ** 2) / (R * Math.sin(theta) ** 2);
      const segments = catmullRomSegments(points, 0).slice(1, -1);
      for (const segment of segments) {
        expect(bezierCurvature(segment, 0)).toBeCloseTo(atJoint, 10);
        for (const t of [0.25, 0.5, 0.75])
          expect(Math.abs(bezierCurvature(segment, t) * R - 1)).toBeLessThan(
            degrees === 15 ? 0.06 : 0.01,
          );
      }
    }
  });

  it('a Catmull-Rom joint is only C¹: κ jumps there unless the points say otherwise', () => {
    const points: Point[] = [
      [0, 0],
      [1, 2],
      [3, 2],
      [4, 0],
      [6, 1],
    ];
    const segments = catmullRomSegments(points, 0);
    const jump = Math.abs(bezierCurvature(segments[1], 1) - bezierCurvature(segments[2], 0));
    expect(jump).toBeGreaterThan(0.1);
  });
});
