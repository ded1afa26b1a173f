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
  /** Steps: degree elevations, levels of subdivision, extra copies of the repeated point. */
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

export const schema: Schema<PropertiesState> = {
  x: choice({ default: 'ends', values: EXPERIMENT_IDS }),
  p: points({ default: LECTURE_CUBIC, min: 2, max: MAX_POINTS }),
  q: points({ default: [], min: 0, max: MAX_POINTS }),
  t: number({ default: 0.3, min: 0, max: 1 }),
  k: int({ default: 0, min: 0, max: MAX_ELEVATIONS }),
  r: int({ default: 1, min: 0, max: MAX_POINTS - 1 }),
  m: choice({ default: 'shear', values: MAP_KINDS }),
};

/** Experiments about cubics only. */
export const needsCubic = (x: ExperimentId) => x === 'cubic' || x === 'hermite';

/** How many steps the experiment has (0: none). */
export function stepCount(state: PropertiesState): number {
  switch (state.x) {
    case 'elevate':
      return MAX_ELEVATIONS;
    case 'split':
      return MAX_SPLITS;
    case 'repeat':
      return MAX_COPIES;
    default:
      return 0;
  }
}

/** What the steps of the experiment show, e.g. "Degree 3 → 5". */
export function describeStep(state: PropertiesState, k: number): string {
  switch (state.x) {
    case 'elevate':
      return k === 0
        ? `Degree ${state.p.length - 1}`
        : `Degree ${state.p.length - 1} → ${state.p.length - 1 + k}`;
    case 'split':
      return `${k} split${k === 1 ? '' : 's'}: ${2 ** k} piece${k === 0 ? '' : 's'}`;
    case 'repeat':
      return `P${state.r} × ${k + 1}`;
    default:
      return '';
  }
}

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
