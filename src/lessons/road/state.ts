import { bool, choice, stepField, linkKey, number, numbers, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { type RoadView, dissects, viewField } from './view';

/** The road the class is discussing: one of the lecture's answers. */
export type RoadMethod = 'roman' | 'quadratic' | 'hermite' | 'natural' | 'clamped' | 'ring';

export const ROAD_METHODS: readonly RoadMethod[] = [
  'roman',
  'quadratic',
  'hermite',
  'natural',
  'clamped',
  'ring',
];

/** Everything the road lesson shows; all of it goes in the link (its key beside each). */
export interface RoadState {
  /** The villages P0 … Pm, in the order the road visits them (`v`). */
  villages: Point[];
  road: RoadMethod;
  /**
   * The road alone, several answers at once with a legend, the natural
   * spline's derivation, or its global change (`overlay`: see view.ts).
   */
  view: RoadView;
  /** The curves drawn in the overlay, as indices into CURVES (see roads.ts). */
  compare: number[];
  /** Gradient D0 at P0 chosen for the quadratic pieces; the first control point is P0 + D0/2 (`q`). */
  quadraticGradient: number[];
  /** Gradients at P0 and Pm where the road meets the other roads, clamped ends (`a`, `b`). */
  startGradient: number[];
  endGradient: number[];
  /** Hermite pieces: use the chosen end gradients instead of zero (the notes' choice). */
  ends: boolean;
  /** Curvature comb along the road. */
  comb: boolean;
  /** The global parameter p̄ of the marker on the road (`s`). */
  pBar: number;
  /** Step of the script (see roadScript in script.ts): 0 the villages, then at most 20 steps. */
  step: number;
}

/** What the road itself is made of: every field but the marker, the comb and the step. */
export type RoadInputs = Pick<
  RoadState,
  | 'villages'
  | 'road'
  | 'view'
  | 'compare'
  | 'quadraticGradient'
  | 'startGradient'
  | 'endGradient'
  | 'ends'
>;

export const MAX_VILLAGES = 600;
/** Village coordinates are kept to 0.01 (a map in km: 10 m), so 500 villages fit in a link. */
const GRID = 100;

export const roundCoordinate = (value: number) => Math.round(value * GRID) / GRID;
export const roundPoint = (p: Point): Point => [roundCoordinate(p[0]), roundCoordinate(p[1])];

/**
 * Six villages inland: a road from the coast (P0) inland to P5. The lesson's
 * own numbers: the notes ask the question without giving villages.
 */
export const SIX_VILLAGES: Point[] = [
  [0, 0],
  [20, 16],
  [42, 10],
  [56, 30],
  [78, 26],
  [92, 44],
];

const gradient = (value: readonly number[], key: string) =>
  linkKey(numbers({ default: value, min: 2, max: 2, low: -1e5, high: 1e5 }), key);

export const schema: Schema<RoadState> = {
  villages: linkKey(points({ default: SIX_VILLAGES, min: 2, max: MAX_VILLAGES, limit: 1e5 }), 'v'),
  road: choice({ default: 'natural', values: ROAD_METHODS }),
  view: linkKey(viewField(), 'overlay'),
  compare: numbers({ default: [0, 2, 3, 6], min: 0, max: 11, low: 0, high: 10 }),
  quadraticGradient: gradient([30, 0], 'q'),
  startGradient: gradient([30, -10], 'a'),
  endGradient: gradient([20, 20], 'b'),
  ends: bool({ default: false }),
  comb: bool({ default: false }),
  pBar: linkKey(number({ default: 2.4, min: 0, max: MAX_VILLAGES }), 's'),
  step: stepField(),
};

/** Segments of the method's road: the ring road has one more, back to P0. */
export const segmentCount = (state: Pick<RoadState, 'road' | 'villages'>) =>
  state.road === 'ring' && state.villages.length >= 3
    ? state.villages.length
    : state.villages.length - 1;

/** Methods whose gradients come from one tridiagonal system solved by the Thomas algorithm. */
export const hasSolve = (state: Pick<RoadState, 'road'>) =>
  state.road === 'natural' || state.road === 'clamped';

/** A long sequence of rows or pieces is stepped in at most this many chunks. */
const CHUNKS = 9;

/** Rows or pieces per step, so that `total` of them take at most CHUNKS steps. */
export const chunkSize = (total: number) => Math.max(1, Math.ceil(total / CHUNKS));
/** Steps for `total` rows or pieces, in chunks. */
export const chunks = (total: number) => Math.ceil(total / chunkSize(total));

/**
 * Cross-field rules: the marker stays on the road; the overlay lists each
 * curve once; the derivation and the global view are of the natural spline.
 */
export function normalize(state: RoadState): { state: RoadState; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  if (dissects(next) && next.road !== 'natural') {
    issues.push(`road: the ${next.view} view is of the natural spline, so road=natural`);
    next = { ...next, road: 'natural' };
  }
  const compare = [...new Set(state.compare.filter((c) => Number.isInteger(c)))];
  if (compare.length !== state.compare.length) {
    issues.push('compare: each curve is listed once, by its whole number');
    next = { ...next, compare };
  }
  const end = segmentCount(next);
  if (next.pBar > end) next = { ...next, pBar: end };
  return { state: next, issues };
}
