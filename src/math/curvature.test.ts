import { Bezier } from 'bezier-js';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, polygon2D } from './arbitraries.test-helpers';
import { bezierDerivative, bezierPoint } from './bezier';
import { bezierCurvature, bezierTangent } from './curvature';
import { bezierFrenetFrame, bezierNormal } from './frenetFrame';
import { osculatingCircle } from './osculatingCircle';
import type { Point } from './vec';

const arc: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];
const inner = fc.double({ min: 0.05, max: 0.95, noNaN: true });

describe('bezierTangent and bezierCurvature', () => {
  it('gives P′ and the lecture’s signed curvature for a parabola', () => {
    // y = x² as the quadratic (0,0), (1/2,0), (1,1): at t = 0, P′ = (1, 0), P″ = (0, 2), κ = 2.
    const parabola: Point[] = [
      [0, 0],
      [0.5, 0],
      [1, 1],
    ];
    expect(bezierTangent(parabola, 0)).toEqual([1, 0]);
    expect(bezierCurvature(parabola, 0)).toBe(2);
    // Mirrored it turns right: κ = −2.
    expect(
      bezierCurvature(
        parabola.map(([x, y]) => [x, -y]),
        0,
      ),
    ).toBe(-2);
  });

  it('is zero on a straight line and 1/r on a circle-like arc', () => {
    expect(
      bezierCurvature(
        [
          [0, 0],
          [1, 1],
          [3, 3],
        ],
        0.3,
      ),
    ).toBeCloseTo(0, 12);
    // The usual cubic quarter circle of radius r, (r,0), (r,kr), (kr,r), (0,r) with
    // k = 4(√2 − 1)/3: at t = 1/2, P′ = r·a·(−1, 1) with a = 3(1/2 − k/4) and
    // P″ = −3kr·(1, 1), so κ = 6a k r² / (2√2 a³ r³) = 3k / (√2 a² r), close to 1/r.
    const k = (4 / 3) * (Math.SQRT2 - 1);
    const a = 3 * (0.5 - k / 4);
    const r = 2;
    const quarter: Point[] = [
      [r, 0],
      [r, k * r],
      [k * r, r],
      [0, r],
    ];
    expect(bezierCurvature(quarter, 0.5)).toBeCloseTo((3 * k) / (Math.SQRT2 * a * a * r), 14);
    expect(bezierCurvature(quarter, 0.5)).toBeCloseTo(1 / r, 2);
  });

  it('agrees with bezier-js curvature', () => {
    fc.assert(
      fc.property(polygon2D(4, 4), inner, (points, t) => {
        const reference = new Bezier(points.map(([x, y]) => ({ x, y }))).curvature(t).k;
        const speed = Math.hypot(...bezierTangent(points, t));
        fc.pre(speed > 1e-3);
        const ours = bezierCurvature(points, t);
        expect(Math.abs(ours - reference)).toBeLessThanOrEqual(
          1e-9 * Math.max(1, Math.abs(reference)),
        );
      }),
    );
  });

  it('gives |P′ × P″| / |P′|³ in 3D, matching 2D for a flat curve', () => {
    fc.assert(
      fc.property(polygon2D(3, 5), inner, (points, t) => {
        fc.pre(Math.hypot(...bezierTangent(points, t)) > 1e-3);
        const lifted = points.map(([x, y]) => [x, y, 7]);
        expect(bezierCurvature(lifted, t)).toBeCloseTo(Math.abs(bezierCurvature(points, t)), 9);
      }),
    );
  });

  it('keeps precision at 1e6 offsets and 1e-6 scales', () => {
    const kappa = bezierCurvature(arc, 0.3);
    expect(
      bezierCurvature(
        arc.map(([x, y]) => [x + 1e6, y + 1e6]),
        0.3,
      ),
    ).toBeCloseTo(kappa, 6);
    expect(
      bezierCurvature(
        arc.map(([x, y]) => [x * 1e-6, y * 1e-6]),
        0.3,
      ) * 1e-6,
    ).toBeCloseTo(kappa, 9);
  });

  it('rejects zero speed', () => {
    const cusp: Point[] = [
      [0, 0],
      [0, 0],
      [1, 1],
    ];
    expect(() => bezierCurvature(cusp, 0)).toThrow(/zero speed at t = 0/);
    expect(() => bezierCurvature([[1, 1]], 0.5)).toThrow(/zero speed/);
    expect(() => bezierTangent(arc, 2)).toThrow(/t = 2 is outside/);
    expect(() => bezierCurvature([[0], [1]], 0.5)).toThrow(/2D and 3D/);
  });
});

describe('bezierFrenetFrame', () => {
  it('in 2D: unit tangent along P′, normal turned left, signed curvature', () => {
    const frame = bezierFrenetFrame(arc, 0.5);
    expectClose(frame.point, [2, 1.5]);
    expectClose(frame.tangent, [1, 0]);
    expectClose(frame.normal, [0, 1]);
    expect(frame.binormal).toBeUndefined();
    expect(frame.curvature).toBe(bezierCurvature(arc, 0.5));
    expectClose(bezierNormal(arc, 0.5), [0, 1]);
  });

  it('in 3D: T, N, B orthonormal and right-handed, N in the plane of P′ and P″', () => {
    fc.assert(
      fc.property(fc.array(point(3), { minLength: 4, maxLength: 4 }), inner, (points, t) => {
        fc.pre(Math.hypot(...bezierTangent(points, t)) > 1e-2);
        const { tangent: T, normal: N, binormal, curvature } = bezierFrenetFrame(points, t);
        const B = binormal as Point;
        const dot = (a: Point, b: Point) => a.reduce((sum, value, d) => sum + value * b[d], 0);
        const cross = (a: Point, b: Point) => [
          a[1] * b[2] - a[2] * b[1],
          a[2] * b[0] - a[0] * b[2],
          a[0] * b[1] - a[1] * b[0],
        ];
        [T, N, B].forEach((v) => expect(dot(v, v)).toBeCloseTo(1, 9));
        expect(dot(T, N)).toBeCloseTo(0, 9);
        expect(dot(T, B)).toBeCloseTo(0, 9);
        expectClose(cross(T, N), B, 1e-9);
        expect(curvature).toBeGreaterThanOrEqual(0);
        const second = bezierPoint(bezierDerivative(bezierDerivative(points)), t);
        // P″ has no component along B, where the osculating plane is well defined:
        // on a nearly straight stretch (P′ and P″ nearly parallel; fast-check found
        // sin θ ≈ 1e-12) rounding in P′ and P″ alone tilts the plane.
        const first = bezierTangent(points, t);
        const sine =
          Math.hypot(...cross(first, second)) / (Math.hypot(...first) * Math.hypot(...second));
        if (sine > 1e-6) {
          expect(Math.abs(dot(second, B))).toBeLessThan(1e-6 * Math.max(1, Math.hypot(...second)));
        }
      }),
    );
  });

  it('picks a perpendicular frame on a straight 3D line', () => {
    const frame = bezierFrenetFrame(
      [
        [0, 0, 0],
        [1, 1, 1],
      ],
      0.5,
    );
    expect(frame.curvature).toBe(0);
    const dot = frame.tangent.reduce((sum, value, d) => sum + value * frame.normal[d], 0);
    expect(dot).toBeCloseTo(0, 12);
  });
});

describe('osculatingCircle', () => {
  it('has radius 1/|κ| and its centre on the normal', () => {
    const circle = osculatingCircle(arc, 0.5);
    // At t = 1/2: P = (2, 1.5), P′ = (4.5, 0), P″ = 3((P3 − P2) − (P1 − P0)) = (0, −12),
    // κ = 4.5·(−12) / 4.5³ = −16/27, so the centre lies 27/16 below P.
    expect(circle.radius).toBeCloseTo(27 / 16, 12);
    expectClose(circle.centre, [2, 1.5 - 27 / 16]);
  });

  it('is close to the unit circle for the cubic quarter-circle approximation', () => {
    const k = (4 / 3) * (Math.SQRT2 - 1);
    const circle = osculatingCircle(
      [
        [1, 0],
        [1, k],
        [k, 1],
        [0, 1],
      ],
      0.5,
    );
    expect(Math.abs(circle.radius - 1)).toBeLessThan(0.01);
    expectClose(circle.centre, [0, 0], 0.01);
  });

  it('rejects zero curvature', () => {
    expect(() =>
      osculatingCircle(
        [
          [0, 0],
          [1, 1],
        ],
        0.5,
      ),
    ).toThrow(/osculatingCircle: the curvature at t = 0.5 is zero/);
    expect(() =>
      osculatingCircle(
        [
          [0, 0],
          [0, 0],
        ],
        0.5,
      ),
    ).toThrow(/osculatingCircle: the curve has zero speed/);
  });
});
