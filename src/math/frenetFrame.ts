import { checkPoints } from './checkPoints';
import { bezierJet, checkSpeed } from './curvature';
import { checkParameter } from './validate';
import type { Point } from './vec';

// The Frenet frame (do Carmo, Differential Geometry of Curves and Surfaces,
// §1.5): unit tangent T = P′/|P′|, binormal B = (P′ × P″)/|P′ × P″|, principal
// normal N = B × T; curvature κ = |P′ × P″|/|P′|³. In 2D the normal is T turned
// a quarter left and κ is signed, so the centre of curvature is P + N/κ in both.

/** The moving frame of a curve at one parameter. */
export interface FrenetFrame {
  /** The point P(t). */
  readonly point: Point;
  /** The unit tangent T. */
  readonly tangent: Point;
  /** The unit normal N: in 2D, T turned 90° anticlockwise; in 3D, the principal normal. */
  readonly normal: Point;
  /** The unit binormal B = T × N (3D only; undefined in 2D). */
  readonly binormal: Point | undefined;
  /** Curvature κ: signed in 2D (positive turning towards N), |κ| in 3D. */
  readonly curvature: number;
}

/**
 * The Frenet frame of a 2D or 3D Bézier curve at t. Where a 3D curve is
 * straight (P″ parallel to P′) N and B are not determined by the curve: a unit
 * vector perpendicular to T is chosen and curvature is 0. RangeError at zero speed.
 */
export function bezierFrenetFrame(points: readonly Point[], t: number): FrenetFrame {
  return frenetFrame('bezierFrenetFrame', points, t);
}

/** bezierFrenetFrame reporting errors under the caller's name. Internal. */
export function frenetFrame(caller: string, points: readonly Point[], t: number): FrenetFrame {
  const dimension = checkPoints(caller, 'points', points, 1);
  checkParameter(caller, 't', t, 0, 1);
  if (dimension !== 2 && dimension !== 3) {
    throw new RangeError(
      `${caller}: points are ${dimension}D; the Frenet frame is defined here for 2D and 3D.`,
    );
  }
  const { point, first, second } = bezierJet(points, dimension, t);
  const speed = checkSpeed(caller, points, first, t);
  const tangent = first.map((value) => value / speed);
  if (dimension === 2) {
    const normal = [-tangent[1], tangent[0]];
    const curvature = (first[0] * second[1] - first[1] * second[0]) / speed ** 3;
    return { point, tangent, normal, binormal: undefined, curvature };
  }
  const crossProduct = [
    first[1] * second[2] - first[2] * second[1],
    first[2] * second[0] - first[0] * second[2],
    first[0] * second[1] - first[1] * second[0],
  ];
  const length = Math.hypot(crossProduct[0], crossProduct[1], crossProduct[2]);
  const scale = speed * Math.hypot(second[0], second[1], second[2]);
  let binormal: number[];
  if (length > 1e-12 * scale && length > 0) {
    binormal = crossProduct.map((value) => value / length);
  } else {
    binormal = unitPerpendicular(tangent);
  }
  const normal = [
    binormal[1] * tangent[2] - binormal[2] * tangent[1],
    binormal[2] * tangent[0] - binormal[0] * tangent[2],
    binormal[0] * tangent[1] - binormal[1] * tangent[0],
  ];
  const curvature = length > 1e-12 * scale ? length / speed ** 3 : 0;
  return { point, tangent, normal, binormal, curvature };
}

/**
 * The unit normal N of a Bézier curve at t (see bezierFrenetFrame): in 2D the
 * unit tangent turned 90° anticlockwise, in 3D the principal normal.
 */
export function bezierNormal(points: readonly Point[], t: number): Point {
  return frenetFrame('bezierNormal', points, t).normal;
}

/** Some unit vector perpendicular to the unit 3D vector v: v × (the axis least parallel to v). */
function unitPerpendicular(v: readonly number[]): number[] {
  const axis =
    Math.abs(v[0]) <= Math.abs(v[1]) && Math.abs(v[0]) <= Math.abs(v[2])
      ? 0
      : Math.abs(v[1]) <= Math.abs(v[2])
        ? 1
        : 2;
  const e = [0, 0, 0];
  e[axis] = 1;
  const c = [v[1] * e[2] - v[2] * e[1], v[2] * e[0] - v[0] * e[2], v[0] * e[1] - v[1] * e[0]];
  const length = Math.hypot(c[0], c[1], c[2]);
  return c.map((value) => value / length);
}
