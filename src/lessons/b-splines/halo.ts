import type { Point } from '../../math';
import { haloIds } from './ids';
import type { BSplineModel, CircleModel, NurbsModel } from './model';
import type { BSplineState } from './state';

/** The weights a slider or a halo can set: the slider's range, inside the link's (above 0). */
export const WEIGHT_MIN = 0.1;
export const WEIGHT_MAX = 5;

/** Share of the control points' extent (bounding-box diagonal) that is one halo unit. */
const UNIT_SHARE = 0.06;
/** A halo's radius in units is BASE + SLOPE·√w: weight 1 is one unit, and 0.1 still clears the point. */
const BASE = 0.3;
const SLOPE = 1 - BASE;

/** The scenes with weight halos (NURBS and the circle), once their step shows the weights. */
export const showsHalos = (m: BSplineModel): m is NurbsModel | CircleModel =>
  (m.kind === 'nurbs' || m.kind === 'circle') && m.shown.has('weights');

/**
 * The world length of one halo unit for these control points: a halo is drawn
 * in world units, so that its radius (and a drag of it) means the same weight
 * at any zoom, and it grows with the figure.
 */
export function haloUnit(points: readonly Point[]): number {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (const [x, y] of points) {
    minX = Math.min(minX, x);
    maxX = Math.max(maxX, x);
    minY = Math.min(minY, y);
    maxY = Math.max(maxY, y);
  }
  const diagonal = Math.hypot(maxX - minX, maxY - minY);
  return UNIT_SHARE * (diagonal > 0 ? diagonal : 1);
}

/** The halo's radius (world) for weight w. */
export const haloRadius = (w: number, unit: number) => unit * (BASE + SLOPE * Math.sqrt(w));

/** The weight whose halo has this radius, kept in [WEIGHT_MIN, WEIGHT_MAX] and to 0.01 (the slider's step). */
export function weightForRadius(radius: number, unit: number): number {
  const root = Math.max(0, (radius / unit - BASE) / SLOPE);
  const w = Math.round(root * root * 100) / 100;
  return Math.min(WEIGHT_MAX, Math.max(WEIGHT_MIN, w));
}

/**
 * The halo ring under `at` (within `tolerance` of its circle), as `w<i>`:
 * of rings that overlap there, the one whose circle is nearest.
 */
export function haloAt(
  points: readonly Point[],
  weights: readonly number[],
  unit: number,
  at: readonly number[],
  tolerance: number,
): string | null {
  let best: string | null = null;
  let distance = tolerance;
  points.forEach((point, i) => {
    const off = Math.abs(
      Math.hypot(at[0] - point[0], at[1] - point[1]) - haloRadius(weights[i], unit),
    );
    if (off <= distance) {
      distance = off;
      best = haloIds.id(i);
    }
  });
  return best;
}

/** The state with weight i set by a halo dragged to `to`: its radius is the distance to P_i. */
export function dragHalo(state: BSplineState, i: number, to: Point, unit: number): BSplineState {
  const point = state.points[i];
  if (!point) return state;
  const w = weightForRadius(Math.hypot(to[0] - point[0], to[1] - point[1]), unit);
  if (w === state.weights[i]) return state;
  return { ...state, weights: state.weights.map((v, k) => (k === i ? w : v)) };
}
