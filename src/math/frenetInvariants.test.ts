import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bezierCurvature } from './curvature';
import { bezierTorsion } from './bezierTorsion';
import { frenetInvariants } from './frenetInvariants';
import { helixDerivatives } from './helix';

describe('frenetInvariants', () => {
  it('gives the helix its closed forms κ = a/(a² + b²), τ = b/(a² + b²)', () => {
    // a = 3, b = 4 at θ = 0: r′ = (0, 3, 4), r″ = (−3, 0, 0), r‴ = (0, −3, 0);
    // r′ × r″ = (0, −12, 9), |·| = 15, κ = 15/125 = 3/25, τ = 36/225 = 4/25.
    const { curvature, torsion } = frenetInvariants([0, 3, 4], [-3, 0, 0], [0, -3, 0]);
    expect(curvature).toBe(3 / 25);
    expect(torsion).toBe(4 / 25);
    fc.assert(
      fc.property(
        fc.double({ min: 0.1, max: 5, noNaN: true }),
        fc.double({ min: -3, max: 3, noNaN: true }),
        fc.double({ min: -20, max: 20, noNaN: true }),
        (a, b, theta) => {
          const k = frenetInvariants(...helixDerivatives(a, b, theta));
          expect(Math.abs(k.curvature - a / (a * a + b * b))).toBeLessThan(1e-12 / a);
          expect(Math.abs(k.torsion - b / (a * a + b * b))).toBeLessThan(1e-12 / a);
        },
      ),
    );
  });

  it('agrees with bezierCurvature and bezierTorsion on a space cubic', () => {
    // Q = (0,0,0), (1,0,0), (1,1,0), (1,1,1) at t = 1/2: P′ = (3/4, 3/2, 3/4),
    // P″ = (−3, 0, 3), P‴ = (6, −12, 6) by differences of the control points.
    const q = [
      [0, 0, 0],
      [1, 0, 0],
      [1, 1, 0],
      [1, 1, 1],
    ];
    const k = frenetInvariants([0.75, 1.5, 0.75], [-3, 0, 3], [6, -12, 6]);
    expect(k.curvature).toBeCloseTo(bezierCurvature(q, 0.5), 14);
    expect(k.torsion).toBeCloseTo(bezierTorsion(q, 0.5), 14);
  });

  it('refuses r′ = 0 and r′ ∥ r″', () => {
    expect(() => frenetInvariants([0, 0, 0], [1, 0, 0], [0, 1, 0])).toThrow(/no direction/);
    expect(() => frenetInvariants([1, 0, 0], [2, 0, 0], [0, 1, 0])).toThrow(
      /torsion are undefined/,
    );
    expect(() => frenetInvariants([1, 0], [2, 0], [0, 1])).toThrow(RangeError);
  });
});
