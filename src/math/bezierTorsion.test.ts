import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { point } from './arbitraries.test-helpers';
import { bezierDerivative, bezierPoint } from './bezier';
import { bezierTangent } from './curvature';
import { bezierFrenetFrame } from './frenetFrame';
import { bezierTorsion } from './bezierTorsion';
import type { Point } from './vec';

// The twisted cubic (3t, 3t², t³) as a Bézier curve: P′ = (3, 6t, 3t²),
// P″ = (0, 6, 6t), P‴ = (0, 0, 6), so P′ × P″ = 18(t², −t, 1) and
// τ = 108 / (324(t⁴ + t² + 1)) = 1 / (3(t⁴ + t² + 1)).
const twisted: Point[] = [
  [0, 0, 0],
  [1, 0, 0],
  [2, 1, 0],
  [3, 3, 1],
];
const inner = fc.double({ min: 0.05, max: 0.95, noNaN: true });
const cubic3D = fc.array(point(3), { minLength: 4, maxLength: 4 });

const cross = (a: Point, b: Point): Point => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const dot = (a: Point, b: Point) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const length = (a: Point) => Math.sqrt(dot(a, a));

/** The derivative of the given order at t, from the hodograph's control points. */
function derivativeAt(points: readonly Point[], t: number, order: number): Point {
  let hodograph: readonly Point[] = points;
  for (let k = 0; k < order; k++) hodograph = bezierDerivative(hodograph);
  return bezierPoint(hodograph, t);
}

/** sin of the angle between P′ and P″: how well the osculating plane is defined. */
function planeSine(points: readonly Point[], t: number): number {
  const [first, second] = [derivativeAt(points, t, 1), derivativeAt(points, t, 2)];
  return length(cross(first, second)) / (length(first) * length(second));
}

describe('bezierTorsion', () => {
  it('gives the twisted cubic’s 1 / (3(t⁴ + t² + 1))', () => {
    expect(bezierTorsion(twisted, 0)).toBe(1 / 3);
    expect(bezierTorsion(twisted, 0.5)).toBe(16 / 63);
    expect(bezierTorsion(twisted, 1)).toBe(1 / 9);
    for (const t of [0.1, 0.3, 0.7, 0.9]) {
      expect(bezierTorsion(twisted, t)).toBeCloseTo(1 / (3 * (t ** 4 + t ** 2 + 1)), 14);
    }
    // Mirrored (z → −z) it twists the other way.
    expect(
      bezierTorsion(
        twisted.map(([x, y, z]) => [x, y, -z]),
        0,
      ),
    ).toBe(-1 / 3);
  });

  it('is 0 for a plane curve, in any plane', () => {
    const flat: Point[] = [
      [0, 0, 0],
      [1, 2, 0],
      [3, 2, 0],
      [4, 0, 0],
    ];
    expect(bezierTorsion(flat, 0.3)).toBe(0);
    const small = fc.integer({ min: -9, max: 9 });
    const vector = fc.tuple(small, small, small);
    fc.assert(
      fc.property(
        point(3),
        vector,
        vector,
        fc.array(fc.tuple(small, small), { minLength: 4, maxLength: 4 }),
        inner,
        (origin, u, v, weights, t) => {
          // Control points origin + a·u + b·v all lie in one plane.
          const points = weights.map(([a, b]) => origin.map((o, d) => o + a * u[d] + b * v[d]));
          fc.pre(length(derivativeAt(points, t, 1)) > 1e-3);
          fc.pre(planeSine(points, t) > 1e-3);
          const third = derivativeAt(points, t, 3);
          const binormal = cross(derivativeAt(points, t, 1), derivativeAt(points, t, 2));
          // τ·|P′ × P″|/|P‴| is the cosine between B and P‴, 0 when P‴ is in the plane.
          const cosine =
            (bezierTorsion(points, t) * length(binormal)) / Math.max(length(third), 1e-300);
          expect(Math.abs(cosine)).toBeLessThan(1e-9);
        },
      ),
    );
  });

  it('agrees with −(dB/ds)·N from finite differences of the Frenet frame', () => {
    fc.assert(
      fc.property(cubic3D, inner, (points, t) => {
        fc.pre(length(bezierTangent(points, t)) > 1);
        fc.pre(planeSine(points, t) > 0.05);
        const h = 1e-5;
        const ahead = bezierFrenetFrame(points, t + h).binormal as Point;
        const behind = bezierFrenetFrame(points, t - h).binormal as Point;
        const { normal } = bezierFrenetFrame(points, t);
        const speed = length(bezierTangent(points, t));
        const dB = ahead.map((value, d) => (value - behind[d]) / (2 * h));
        const estimate = -dot(dB, normal) / speed;
        const tau = bezierTorsion(points, t);
        expect(Math.abs(tau - estimate)).toBeLessThan(1e-4 * Math.max(1, Math.abs(tau)));
      }),
    );
  });

  it('is unchanged by moving, turning or reversing the curve, and scales as 1/length', () => {
    fc.assert(
      fc.property(cubic3D, inner, point(3), (points, t, shift) => {
        fc.pre(length(bezierTangent(points, t)) > 1);
        fc.pre(planeSine(points, t) > 0.05);
        const tau = bezierTorsion(points, t);
        const tolerance = 1e-7 * Math.max(1, Math.abs(tau));
        // A rotation about z by 90° and a shift.
        const moved = points.map(([x, y, z]) => [-y + shift[0], x + shift[1], z + shift[2]]);
        expect(Math.abs(bezierTorsion(moved, t) - tau)).toBeLessThan(tolerance);
        expect(Math.abs(bezierTorsion(points.slice().reverse(), 1 - t) - tau)).toBeLessThan(
          tolerance,
        );
        const doubled = points.map((p) => p.map((value) => 2 * value));
        expect(bezierTorsion(doubled, t)).toBeCloseTo(tau / 2, 12);
      }),
    );
  });

  it('is 0 below degree 3, where the curve is plane', () => {
    expect(
      bezierTorsion(
        [
          [0, 0, 0],
          [1, 1, 0],
          [2, 0, 1],
        ],
        0.5,
      ),
    ).toBe(0);
  });

  it('rejects 2D points and points where P′ × P″ = 0', () => {
    expect(() =>
      bezierTorsion(
        [
          [0, 0],
          [1, 2],
          [3, 2],
          [4, 0],
        ],
        0.5,
      ),
    ).toThrow('bezierTorsion: points are 2D; torsion is defined for 3D curves');
    const straight: Point[] = [
      [0, 0, 0],
      [1, 1, 1],
      [2, 2, 2],
      [3, 3, 3],
    ];
    expect(() => bezierTorsion(straight, 0.5)).toThrow(/P′ × P″ = 0 at t = 0.5/);
    expect(() => bezierTorsion(straight.slice(0, 2), 0.5)).toThrow(/P′ × P″ = 0/);
    // An S-shaped plane cubic has an inflection at t = 1/2, where P″ ∥ P′.
    const inflection: Point[] = [
      [0, 0, 0],
      [1, 1, 0],
      [2, -1, 0],
      [3, 0, 0],
    ];
    expect(() => bezierTorsion(inflection, 0.5)).toThrow(/P′ × P″ = 0/);
    const cusp: Point[] = [
      [0, 0, 0],
      [0, 0, 0],
      [1, 1, 1],
    ];
    expect(() => bezierTorsion(cusp, 0)).toThrow(/zero speed/);
    expect(() => bezierTorsion(twisted, 1.5)).toThrow(/t = 1.5 is outside/);
    expect(() => bezierTorsion([[0, 0, NaN]], 0)).toThrow(RangeError);
  });
});
