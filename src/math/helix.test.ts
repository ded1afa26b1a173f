import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { helixCurvature, helixFrame, helixPoint, helixTorsion } from './helix';

const dot = (u: readonly number[], v: readonly number[]) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
const cross = (u: readonly number[], v: readonly number[]) => [
  u[1] * v[2] - u[2] * v[1],
  u[2] * v[0] - u[0] * v[2],
  u[0] * v[1] - u[1] * v[0],
];

describe('helix', () => {
  it('has the closed forms κ = a/(a² + b²), τ = b/(a² + b²)', () => {
    // a = 1, b = 1: κ = τ = 1/2. a = 3, b = 4: κ = 3/25, τ = 4/25. a = 2, b = 0 is a circle.
    expect(helixCurvature(1, 1)).toBe(0.5);
    expect(helixTorsion(1, 1)).toBe(0.5);
    expect(helixCurvature(3, 4)).toBe(3 / 25);
    expect(helixTorsion(3, 4)).toBe(4 / 25);
    expect(helixCurvature(2, 0)).toBe(0.5);
    expect(helixTorsion(2, 0)).toBe(0);
    expect(helixTorsion(3, -4)).toBe(-4 / 25);
  });

  it('gives the frame of the lecture example at θ = 0 and θ = π/2', () => {
    // a = 3, b = 4, c = 5: at θ = 0, T = (0, 3, 4)/5, N = (−1, 0, 0), B = (0, −4, 3)/5.
    const f = helixFrame(3, 4, 0);
    expect(f.point).toEqual([3, 0, 0]);
    expect(f.tangent.map((v) => v + 0)).toEqual([0, 0.6, 0.8]);
    expect(f.normal.map((v) => v + 0)).toEqual([-1, 0, 0]);
    expect(f.binormal.map((v) => v + 0)).toEqual([0, -0.8, 0.6]);
    expect(f.speed).toBe(5);
    const g = helixFrame(3, 4, Math.PI / 2);
    expect(g.point[2]).toBeCloseTo(2 * Math.PI, 14);
    expect(g.tangent[0]).toBeCloseTo(-0.6, 15);
    expect(g.normal[1]).toBeCloseTo(-1, 15);
  });

  it('is a right-handed orthonormal frame that obeys Frenet–Serret', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.2, max: 5, noNaN: true }),
        fc.double({ min: -3, max: 3, noNaN: true }),
        fc.double({ min: -10, max: 10, noNaN: true }),
        (a, b, theta) => {
          const f = helixFrame(a, b, theta);
          for (const v of [f.tangent, f.normal, f.binormal]) expect(dot(v, v)).toBeCloseTo(1, 12);
          expect(dot(f.tangent, f.normal)).toBeCloseTo(0, 12);
          cross(f.tangent, f.normal).forEach((v, i) => expect(v).toBeCloseTo(f.binormal[i], 12));
          // dT/ds = κN and dB/ds = −τN, by central differences in θ (ds = c dθ).
          const h = 1e-5;
          const [before, after] = [helixFrame(a, b, theta - h), helixFrame(a, b, theta + h)];
          const ds = 2 * h * f.speed;
          for (let i = 0; i < 3; i++) {
            expect((after.tangent[i] - before.tangent[i]) / ds).toBeCloseTo(
              f.curvature * f.normal[i],
              6,
            );
            expect((after.binormal[i] - before.binormal[i]) / ds).toBeCloseTo(
              -f.torsion * f.normal[i],
              6,
            );
          }
          // r′ = (r(θ + h) − r(θ − h))/2h points along T with length c.
          const [p, q] = [helixPoint(a, b, theta - h), helixPoint(a, b, theta + h)];
          for (let i = 0; i < 3; i++)
            expect((q[i] - p[i]) / (2 * h)).toBeCloseTo(f.speed * f.tangent[i], 6);
        },
      ),
    );
  });

  it('refuses a radius that is not positive', () => {
    expect(() => helixFrame(0, 1, 0)).toThrow(RangeError);
    expect(() => helixCurvature(-1, 1)).toThrow(/radius must be positive/);
    expect(() => helixPoint(1, Number.NaN, 0)).toThrow(RangeError);
  });
});
