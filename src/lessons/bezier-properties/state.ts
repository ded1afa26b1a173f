import { choice, int, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/** The experiments of the lesson, one per property (`x=hull` in the link). */
export type ExperimentId =
  | 'ends'
  | 'hull'
  | 'local'
  | 'repeat'
  | 'closed'
  | 'elevate'
  | 'split'
  | 'affine'
  | 'cubic'
  | 'hermite';

/** The plane maps of the affine-invariance experiment. */
export type MapKind = 'rotate' | 'scale' | 'shear' | 'perspective';

/** Everything the lesson shows, and all of it goes in the link. */
export interface PropertiesState {
  /** The experiment shown. */
  x: ExperimentId;
  /** The control points the user moves (for `repeat` and `closed`, before repeating). */
  p: Point[];
  /** The "before" control points of the local-control experiment. */
  q: Point[];
  /** A parameter: the point P(t), the split parameter. */
  t: number;
  /**
   * The step of the experiment (see STAGES): 0 the control points, then one
   * thing more per step; for elevation, subdivision and the repeated point,
   * step 1 is the curve and each later step one elevation, split or copy.
   */
  k: number;
  /** The index of the repeated point. */
  r: number;
  /** The map of the affine-invariance experiment. */
  m: MapKind;
}

export const MAX_POINTS = 16;
export const MAX_ELEVATIONS = 12;
export const MAX_SPLITS = 5;
export const MAX_COPIES = 5;

export const LECTURE_CUBIC: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

export const EXPERIMENT_IDS: readonly ExperimentId[] = [
  'ends',
  'hull',
  'local',
  'repeat',
  'closed',
  'elevate',
  'split',
  'affine',
  'cubic',
  'hermite',
];

export const MAP_KINDS: readonly MapKind[] = ['rotate', 'scale', 'shear', 'perspective'];

/**
 * The step at which each experiment shows each thing (step 0 shows only the
 * control points). Elevation, subdivision and the repeated point show the
 * curve at step 1 and then one elevation, split or copy per step.
 */
export const STAGES = {
  ends: { polygon: 1, curve: 2, ends: 3, tangents: 4, point: 5 },
  hull: { polygon: 1, hull: 2, curve: 3, point: 4 },
  local: { before: 1, moved: 2, curve: 3, largest: 4 },
  repeat: { curve: 1 },
  closed: { polygon: 1, curve: 2, tangents: 3, point: 4 },
  elevate: { curve: 1 },
  split: { curve: 1 },
  affine: { curve: 1, mappedPoints: 2, curveOfMapped: 3, mappedCurve: 4, point: 5 },
  cubic: { polygon: 1, curve: 2, turning: 3, marks: 4, point: 5 },
  hermite: { curve: 1, tangents: 2, hermite: 3, point: 4 },
} as const satisfies Record<ExperimentId, Record<string, number>>;

export const schema: Schema<PropertiesState> = {
  x: choice({ default: 'ends', values: EXPERIMENT_IDS }),
  p: points({ default: LECTURE_CUBIC, min: 2, max: MAX_POINTS }),
  q: points({ default: [], min: 0, max: MAX_POINTS }),
  t: number({ default: 0.3, min: 0, max: 1 }),
  // A student who opens the link sees the first experiment whole: its last step.
  k: int({ default: STAGES.ends.point, min: 0, max: 1 + MAX_ELEVATIONS }),
  r: int({ default: 1, min: 0, max: MAX_POINTS - 1 }),
  m: choice({ default: 'shear', values: MAP_KINDS }),
};

/** Experiments about cubics only. */
export const needsCubic = (x: ExperimentId) => x === 'cubic' || x === 'hermite';

/** The most of each experiment's own steps: elevations, splits, extra copies. */
const AMOUNTS: Partial<Record<ExperimentId, number>> = {
  elevate: MAX_ELEVATIONS,
  split: MAX_SPLITS,
  repeat: MAX_COPIES,
};

/** How many steps the experiment has: its last step shows everything. */
export function stepCount(state: PropertiesState): number {
  const amount = AMOUNTS[state.x];
  return amount === undefined ? Math.max(...Object.values(STAGES[state.x])) : 1 + amount;
}

/** Elevations, splits or extra copies shown at the current step (0 up to step 1). */
export const amount = (state: PropertiesState) => Math.max(0, state.k - 1);

/** The step that shows `n` elevations, splits or extra copies. */
export const stepFor = (n: number) => n + 1;

const copy = (list: readonly Point[]): Point[] => list.map((point) => [...point]);

/** Cross-field rules: a cubic for the cubic experiments, a "before" that matches, a valid repeated point. */
export function normalize(state: PropertiesState): { state: PropertiesState; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  if (needsCubic(next.x) && next.p.length !== 4) {
    issues.push(
      `this experiment is about cubics, which have 4 control points, not ${next.p.length}; the lecture cubic is shown`,
    );
    next = { ...next, p: copy(LECTURE_CUBIC) };
  }
  if (next.x === 'local' && next.q.length !== next.p.length) {
    if (next.q.length > 0) {
      issues.push(
        `the "before" curve had ${next.q.length} control points and the curve ${next.p.length}; the current curve is now the "before" one`,
      );
    }
    next = { ...next, q: copy(next.p) };
  }
  if (next.r >= next.p.length) {
    issues.push(`there is no P${next.r} to repeat; P1 is repeated instead`);
    next = { ...next, r: Math.min(1, next.p.length - 1) };
  }
  return { state: next, issues };
}
