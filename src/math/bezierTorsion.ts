import { checkPoints } from './checkPoints';
import { bezierJet, checkSpeed } from './curvature';
import { checkParameter } from './validate';
import type { Point } from './vec';

// Torsion (do Carmo, Differential Geometry of Curves and Surfaces, §1.5):
// τ = ((P′ × P″) · P‴) / |P′ × P″|², how fast the osculating plane turns about
// the tangent; positive for a right-handed helix, 0 for a plane curve. P‴ is
// n(n−1)(n−2) times the degree n−3 Bézier curve of the third differences
// Δ³Pi = P(i+3) − 3P(i+2) + 3P(i+1) − Pi (Farin, Curves and Surfaces for CAGD, §5.3).

/**
 * The torsion of a 3D Bézier curve at t. RangeError for 2D points and where
 * P′ × P″ = 0 (zero speed, a straight stretch or an inflection), since the
 * osculating plane, and so the Frenet frame, is undefined there.
 */
export function bezierTorsion(points: readonly Point[], t: number): number {
  const caller = 'bezierTorsion';
  const dimension = checkPoints(caller, 'points', points, 1);
  checkParameter(caller, 't', t, 0, 1);
  if (dimension !== 3) {
    throw new RangeError(
      `${caller}: points are ${dimension}D; torsion is defined for 3D curves (a plane curve has torsion 0).`,
    );
  }
  const { first, second } = bezierJet(points, 3, t);
  const speed = checkSpeed(caller, points, first, t);
  const cx = first[1] * second[2] - first[2] * second[1];
  const cy = first[2] * second[0] - first[0] * second[2];
  const cz = first[0] * second[1] - first[1] * second[0];
  const crossSquared = cx * cx + cy * cy + cz * cz;
  // The same test as bezierFrenetFrame's: below it rounding alone sets the plane.
  const scale = speed * Math.hypot(second[0], second[1], second[2]);
  if (!(Math.sqrt(crossSquared) > 1e-12 * scale)) {
    throw new RangeError(
      `${caller}: P′ × P″ = 0 at t = ${t} (the curve is straight there or has an inflection), so its osculating plane and torsion are undefined; try another t.`,
    );
  }
  const [tx, ty, tz] = thirdDerivative(points, t);
  return (cx * tx + cy * ty + cz * tz) / crossSquared;
}

/** P‴(t) of a 3D Bézier curve (the zero vector below degree 3). */
function thirdDerivative(points: readonly Point[], t: number): [number, number, number] {
  const n = points.length - 1;
  const third: [number, number, number] = [0, 0, 0];
  if (n < 3) return third;
  const row = new Float64Array(n - 2);
  const s = 1 - t;
  const factor = n * (n - 1) * (n - 2);
  for (let d = 0; d < 3; d++) {
    for (let i = 0; i + 3 <= n; i++) {
      row[i] = points[i + 3][d] - 3 * points[i + 2][d] + 3 * points[i + 1][d] - points[i][d];
    }
    for (let r = n - 3; r > 0; r--) {
      for (let i = 0; i < r; i++) row[i] = s * row[i] + t * row[i + 1];
    }
    third[d] = factor * row[0];
  }
  return third;
}
