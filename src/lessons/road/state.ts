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
  /** Step of the script: 0 the villages, then the method's construction in at most 20 steps (see stage). */
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
  step: int({ default: 0, min: 0, max: 20 }),
};

/** Segments of the method's road: the ring road has one more, back to P0. */
export const segmentCount = (state: RoadState) =>
  state.road === 'ring' && state.v.length >= 3 ? state.v.length : state.v.length - 1;

/** Methods whose gradients come from one tridiagonal system solved by the Thomas algorithm. */
export const hasSolve = (state: RoadState) => state.road === 'natural' || state.road === 'clamped';

/** A long sequence of rows or pieces is stepped in at most this many chunks. */
const CHUNKS = 9;

/** Rows or pieces per step, so that `total` of them take at most CHUNKS steps. */
export const chunkSize = (total: number) => Math.max(1, Math.ceil(total / CHUNKS));
/** Steps for `total` rows or pieces, in chunks. */
const chunks = (total: number) => Math.ceil(total / chunkSize(total));

/** Does the method show a construction (gradients, B0, a system) before its first piece? */
const hasAid = (state: RoadState) => state.road !== 'roman';

/**
 * Steps of the script. Step 0 shows the villages alone. With the overlay, each
 * step adds one curve. Natural and clamped: the system, then its forward sweep
 * row by row, then the back substitution one gradient at a time (each in
 * chunks on a long road), the road growing from its end. The others: their
 * construction (gradients, the first control point, the cyclic system), then
 * the pieces from P0 onwards, in chunks.
 */
export function stepCount(state: RoadState): number {
  if (state.overlay) return Math.max(1, state.compare.length);
  if (hasSolve(state)) return 1 + 2 * chunks(state.v.length);
  return (hasAid(state) ? 1 : 0) + chunks(segmentCount(state));
}

/** What the step shows. */
export interface RoadStage {
  /** The villages alone. */
  bare: boolean;
  /** Natural and clamped: the step of the solve, 0 (the system) … 2n (solved); else null. */
  solveStep: number | null;
  /** Other methods: the pieces shown, from P0 (all of them at the last step). */
  pieces: number;
  /** The overlay: its first `curves` curves are drawn. */
  curves: number;
}

export function stage(state: RoadState): RoadStage {
  const k = Math.min(state.step, stepCount(state));
  const segments = segmentCount(state);
  const bare = k === 0;
  if (state.overlay) return { bare, solveStep: null, pieces: segments, curves: k };
  if (hasSolve(state)) {
    const n = state.v.length;
    const size = chunkSize(n);
    const sweep = chunks(n);
    const solveStep =
      k <= 1
        ? 0
        : k <= 1 + sweep
          ? Math.min(n, (k - 1) * size)
          : n + Math.min(n, (k - 1 - sweep) * size);
    return { bare, solveStep, pieces: segments, curves: 0 };
  }
  const built = k - (hasAid(state) ? 1 : 0);
  return {
    bare,
    solveStep: null,
    pieces: Math.min(segments, Math.max(0, built) * chunkSize(segments)),
    curves: 0,
  };
}

/** Is the road being built step by step (so only part of it is shown)? */
export function isSolving(state: RoadState): boolean {
  return state.step < stepCount(state);
}

/** Keeps "the whole road shown" when the number of steps changes. */
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
