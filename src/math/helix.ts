import { checkNumber } from './validate';
import type { Point } from './vec';

// The circular helix r(θ) = (a cos θ, a sin θ, bθ), radius a > 0, rise b per
// radian. Its Frenet frame and invariants have closed forms (do Carmo,
// Differential Geometry of Curves and Surfaces, §1.5, Exercise 1): with
// c = √(a² + b²), |r′| = c, T = (−a sin θ, a cos θ, b)/c, N = (−cos θ, −sin θ, 0)
// (towards the axis), B = T × N = (b sin θ, −b cos θ, a)/c, and constant
// κ = a/c², τ = b/c².

/** The Frenet frame of the helix at θ, with its speed and invariants. */
export interface HelixFrame {
  readonly point: Point;
  readonly tangent: Point;
  readonly normal: Point;
  readonly binormal: Point;
  /** |r′(θ)| = √(a² + b²). */
  readonly speed: number;
  /** κ = a/(a² + b²). */
  readonly curvature: number;
  /** τ = b/(a² + b²): positive for a right-handed helix (b > 0). */
  readonly torsion: number;
}

function checkHelix(caller: string, a: number, b: number): void {
  checkNumber(caller, 'b', b);
  if (!(a > 0) || !Number.isFinite(a)) {
    throw new RangeError(
      `${caller}: a = ${a}; the helix radius must be positive (a = 0 is the straight z axis, whose normal is undefined).`,
    );
  }
}

/** The point (a cos θ, a sin θ, bθ) of the helix. */
export function helixPoint(a: number, b: number, theta: number): Point {
  checkHelix('helixPoint', a, b);
  checkNumber('helixPoint', 'theta', theta);
  return [a * Math.cos(theta), a * Math.sin(theta), b * theta];
}

/** The curvature a/(a² + b²) of the helix (the same at every point). */
export function helixCurvature(a: number, b: number): number {
  checkHelix('helixCurvature', a, b);
  return a / (a * a + b * b);
}

/** The torsion b/(a² + b²) of the helix (the same at every point). */
export function helixTorsion(a: number, b: number): number {
  checkHelix('helixTorsion', a, b);
  return b / (a * a + b * b);
}

/** The Frenet frame T, N, B of the helix at θ, from the closed forms. */
export function helixFrame(a: number, b: number, theta: number): HelixFrame {
  checkHelix('helixFrame', a, b);
  checkNumber('helixFrame', 'theta', theta);
  const [cos, sin] = [Math.cos(theta), Math.sin(theta)];
  const squared = a * a + b * b;
  const speed = Math.sqrt(squared);
  return {
    point: [a * cos, a * sin, b * theta],
    tangent: [(-a * sin) / speed, (a * cos) / speed, b / speed],
    normal: [-cos, -sin, 0],
    binormal: [(b * sin) / speed, (-b * cos) / speed, a / speed],
    speed,
    curvature: a / squared,
    torsion: b / squared,
  };
}

/** r′(θ), r″(θ), r‴(θ) of the helix, for the general formulas of κ and τ. */
export function helixDerivatives(a: number, b: number, theta: number): [Point, Point, Point] {
  checkHelix('helixDerivatives', a, b);
  checkNumber('helixDerivatives', 'theta', theta);
  const [cos, sin] = [Math.cos(theta), Math.sin(theta)];
  return [
    [-a * sin, a * cos, b],
    [-a * cos, -a * sin, 0],
    [a * sin, -a * cos, 0],
  ];
}
