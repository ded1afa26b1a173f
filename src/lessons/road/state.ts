import type { Point2 } from '../../app/lesson';
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
  v: Point2[];
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
export const roundPoint = (p: readonly number[]): Point2 => [
  roundCoordinate(p[0]),
  roundCoordinate(p[1]),
];

/** The lecture's villages: a road from the coast (P0) inland to P5. */
export const LECTURE_VILLAGES: Point2[] = [
  [0, 0],
  [20, 16],
  [42, 10],
  [56, 30],
  [78, 26],
  [92, 44],
];

export const schema: Schema<RoadState> = {
  v: { kind: 'points', default: LECTURE_VILLAGES, min: 2, max: MAX_VILLAGES, limit: 1e5 },
  road: { kind: 'enum', default: 'natural', values: ROAD_METHODS },
  overlay: { kind: 'bool', default: false },
  compare: { kind: 'numbers', default: [0, 2, 3, 6], min: 0, max: 11, low: 0, high: 10 },
  q: { kind: 'numbers', default: [30, 0], min: 2, max: 2, low: -1e5, high: 1e5 },
  a: { kind: 'numbers', default: [30, -10], min: 2, max: 2, low: -1e5, high: 1e5 },
  b: { kind: 'numbers', default: [20, 20], min: 2, max: 2, low: -1e5, high: 1e5 },
  ends: { kind: 'bool', default: false },
  comb: { kind: 'bool', default: false },
  s: { kind: 'number', default: 2.4, min: 0, max: MAX_VILLAGES },
  step: { kind: 'int', default: 2 * MAX_VILLAGES, min: 0, max: 2 * MAX_VILLAGES },
};

/** m: the index of the last village (m + 1 villages, m segments on an open road). */
export const lastIndex = (state: RoadState) => state.v.length - 1;

/** Segments of the method's road: the ring road has one more, back to P0. */
export const segmentCount = (state: RoadState) =>
  state.road === 'ring' && state.v.length >= 3 ? state.v.length : state.v.length - 1;

/** Methods whose gradients come from one tridiagonal system solved by the Thomas algorithm. */
export const hasSolve = (state: RoadState) => state.road === 'natural' || state.road === 'clamped';

/** Steps of the solve: each row swept, then each D fixed (2(m + 1)); none for other methods. */
export const stepCount = (state: RoadState) => (hasSolve(state) ? 2 * state.v.length : 0);

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

/** A small seeded generator (mulberry32), so a preset is the same in every browser and test. */
export function seededRandom(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * `count` villages up a winding valley: hairpin bends climbing a hillside, each
 * village a little off the valley floor. Deterministic for a given count.
 */
export function valleyVillages(count: number, seed = 6): Point2[] {
  const random = seededRandom(seed);
  const villages: Point2[] = [];
  const bends = Math.max(1, Math.round(count / 80));
  for (let i = 0; i < count; i++) {
    const u = count === 1 ? 0 : i / (count - 1);
    const x = 70 + 62 * Math.sin(Math.PI * (bends * u - 0.5));
    const y = 100 * u + 3 * Math.sin(9 * Math.PI * u);
    villages.push(roundPoint([x + (random() - 0.5) * 1.6, y + (random() - 0.5) * 1.6]));
  }
  return villages;
}

/**
 * A new village goes into the stretch of road it is nearest to (the same rule
 * as adding a control point in the de Casteljau lesson).
 */
export const insertVillage = (villages: readonly Point2[], at: Point2): Point2[] =>
  insertPoint(villages, roundPoint(at));
