import { bool, choice, int, number, numbers, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { insertPoint } from '../../interact/editPoints';

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

/** Everything the road lesson shows; all of it goes in the link. */
export interface RoadState {
  /** The villages P0 … Pm, in the order the road visits them. */
  v: Point[];
  road: RoadMethod;
  /** Draw several answers at once, with a legend. */
  overlay: boolean;
  /** The curves drawn in the overlay, as indices into CURVES (see roads.ts). */
  compare: number[];
  /** Gradient D0 at P0 chosen for the quadratic pieces (the first control point is P0 + D0/2). */
  q: number[];
  /** Gradients at P0 and Pm where the road meets the other roads (clamped ends). */
  a: number[];
  b: number[];
  /** Hermite pieces: use the chosen end gradients a, b instead of zero (the notes' choice). */
  ends: boolean;
  /** Curvature comb along the road. */
  comb: boolean;
  /** The global parameter p̄ of the marker on the road. */
  s: number;
  /** Step of the solve: 0 (the system), n sweep steps, then n back-substitution steps. */
  step: number;
}

export const MAX_VILLAGES = 600;
/** Village coordinates are kept to 0.01 (a map in km: 10 m), so 500 villages fit in a link. */
const GRID = 100;

export const roundCoordinate = (value: number) => Math.round(value * GRID) / GRID;
export const roundPoint = (p: Point): Point => [roundCoordinate(p[0]), roundCoordinate(p[1])];

/** The lecture's villages: a road from the coast (P0) inland to P5. */
export const LECTURE_VILLAGES: Point[] = [
  [0, 0],
  [20, 16],
  [42, 10],
  [56, 30],
  [78, 26],
  [92, 44],
];

const gradient = (value: readonly number[]) =>
  numbers({ default: value, min: 2, max: 2, low: -1e5, high: 1e5 });

export const schema: Schema<RoadState> = {
  v: points({ default: LECTURE_VILLAGES, min: 2, max: MAX_VILLAGES, limit: 1e5 }),
  road: choice({ default: 'natural', values: ROAD_METHODS }),
  overlay: bool({ default: false }),
  compare: numbers({ default: [0, 2, 3, 6], min: 0, max: 11, low: 0, high: 10 }),
  q: gradient([30, 0]),
  a: gradient([30, -10]),
  b: gradient([20, 20]),
  ends: bool({ default: false }),
  comb: bool({ default: false }),
  s: number({ default: 2.4, min: 0, max: MAX_VILLAGES }),
  step: int({ default: 2 * MAX_VILLAGES, min: 0, max: 2 * MAX_VILLAGES }),
};

/** Segments of the method's road: the ring road has one more, back to P0. */
export const segmentCount = (state: RoadState) =>
  state.road === 'ring' && state.v.length >= 3 ? state.v.length : state.v.length - 1;

/** Methods whose gradients come from one tridiagonal system solved by the Thomas algorithm. */
export const hasSolve = (state: RoadState) => state.road === 'natural' || state.road === 'clamped';

/** Steps of the solve: each row swept, then each D fixed (2(m + 1)); none for other methods. */
export const stepCount = (state: RoadState) => (hasSolve(state) ? 2 * state.v.length : 0);

/** Is the solve being stepped through (so only part of the road is built)? */
export const isSolving = (state: RoadState) => hasSolve(state) && state.step < stepCount(state);

/** Keeps "the whole solve shown" when the number of steps changes. */
export function keepStepEnd(before: RoadState, after: RoadState): RoadState {
  return before.step >= stepCount(before) ? { ...after, step: stepCount(after) } : after;
}

/** Cross-field rules: the marker stays on the road; the overlay lists each curve once. */
export function normalize(state: RoadState): { state: RoadState; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  const compare = [...new Set(state.compare.filter((c) => Number.isInteger(c)))];
  if (compare.length !== state.compare.length) {
    issues.push('compare: each curve is listed once, by its whole number');
    next = { ...next, compare };
  }
  const end = segmentCount(next);
  if (next.s > end) next = { ...next, s: end };
  return { state: next, issues };
}

/**
 * A new village goes into the stretch of road it is nearest to (the same rule
 * as adding a control point in the de Casteljau lesson).
 */
export const insertVillage = (villages: readonly Point[], at: Point): Point[] =>
  insertPoint(villages, roundPoint(at));
