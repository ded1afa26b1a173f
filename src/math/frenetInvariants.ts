import { checkPoint } from './checkPoints';
import type { Point } from './vec';

// Curvature and torsion of any regular space curve from its first three
// derivatives at one parameter (do Carmo, Differential Geometry of Curves and
// Surfaces, §1.5): κ = |r′ × r″|/|r′|³, τ = ((r′ × r″) · r‴)/|r′ × r″|². Neither
// depends on how the curve is parametrised.

/** κ and τ of a space curve at one parameter. */
export interface FrenetInvariants {
  readonly curvature: number;
  readonly torsion: number;
}

/**
 * κ and τ from r′, r″, r‴ (3D vectors). RangeError where r′ = 0 (no direction)
 * or r′ × r″ = 0 (κ = 0: no osculating plane, so τ is undefined).
 */
export function frenetInvariants(first: Point, second: Point, third: Point): FrenetInvariants {
  const caller = 'frenetInvariants';
  checkPoint(caller, 'first', first, 3);
  checkPoint(caller, 'second', second, 3);
  checkPoint(caller, 'third', third, 3);
  const speed = Math.hypot(first[0], first[1], first[2]);
  if (!(speed > 0)) {
    throw new RangeError(`${caller}: r′ = 0, so the curve has no direction and no frame here.`);
  }
  const c = [
    first[1] * second[2] - first[2] * second[1],
    first[2] * second[0] - first[0] * second[2],
    first[0] * second[1] - first[1] * second[0],
  ];
  const crossLength = Math.hypot(c[0], c[1], c[2]);
  if (!(crossLength > 1e-14 * speed * Math.hypot(second[0], second[1], second[2]))) {
    throw new RangeError(
      `${caller}: r′ × r″ = 0 (κ = 0), so the osculating plane and the torsion are undefined here.`,
    );
  }
  return {
    curvature: crossLength / speed ** 3,
    torsion: (c[0] * third[0] + c[1] * third[1] + c[2] * third[2]) / crossLength ** 2,
  };
}
