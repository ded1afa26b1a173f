import { choice, int, stepField, linkKey, number, points } from '../../app/fields';
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
  | 'hermite'
  | 'hodograph';

/** The plane maps of the affine-invariance experiment. */
export type MapKind = 'rotate' | 'scale' | 'shear' | 'perspective';

/**
 * Everything the lesson shows, and all of it goes in the link, each field
 * under its one-letter key (`x p q t k r m`, in this order).
 */
export interface PropertiesState {
  /** The experiment shown (`x`): it says which scene's steps the state walks. */
  experiment: ExperimentId;
  /** The control points the user moves (`p`; for `repeat` and `closed`, before repeating). */
  points: Point[];
  /** The "before" control points of the local-control experiment (`q`). */
  before: Point[];
  /** A parameter: the point P(t), the split parameter. */
  t: number;
  /** The step of the experiment's script (`k`; see each experiment's script.ts). */
  step: number;
  /** The index of the repeated point (`r`). */
  repeated: number;
  /** The map of the affine-invariance experiment (`m`). */
  map: MapKind;
}

export const MAX_POINTS = 16;
export const MAX_ELEVATIONS = 12;
export const MAX_SPLITS = 5;
export const MAX_COPIES = 5;

/**
 * The lesson's own cubic, a symmetric arch (the notes' figures give no
 * coordinates, so it is not theirs): P(0.5) = (2, 1.5).
 */
export const ARCH_CUBIC: Point[] = [
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
  'hodograph',
];

export const MAP_KINDS: readonly MapKind[] = ['rotate', 'scale', 'shear', 'perspective'];

export const schema: Schema<PropertiesState> = {
  experiment: linkKey(choice({ default: 'ends', values: EXPERIMENT_IDS }), 'x'),
  points: linkKey(points({ default: ARCH_CUBIC, min: 2, max: MAX_POINTS }), 'p'),
  before: linkKey(points({ default: [], min: 0, max: MAX_POINTS }), 'q'),
  t: number({ default: 0.3, min: 0, max: 1 }),
  // Every lesson opens at its first scene's step 0: the first clicker press is the first step.
  step: linkKey(stepField(), 'k'),
  repeated: linkKey(int({ default: 1, min: 0, max: MAX_POINTS - 1 }), 'r'),
  map: linkKey(choice({ default: 'shear', values: MAP_KINDS }), 'm'),
};

/** Experiments about cubics only. */
export const needsCubic = (experiment: ExperimentId) =>
  experiment === 'cubic' || experiment === 'hermite';

export const copy = (list: readonly Point[]): Point[] => list.map((point) => [...point]);

/** Cross-field rules: a cubic for the cubic experiments, a "before" that matches, a valid repeated point. */
export function normalize(state: PropertiesState): { state: PropertiesState; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  if (needsCubic(next.experiment) && next.points.length !== 4) {
    issues.push(
      `this experiment is about cubics, which have 4 control points, not ${next.points.length}; the arch cubic (0, 0), (1, 2), (3, 2), (4, 0) is shown`,
    );
    next = { ...next, points: copy(ARCH_CUBIC) };
  }
  if (next.experiment === 'local' && next.before.length !== next.points.length) {
    if (next.before.length > 0) {
      issues.push(
        `the "before" curve had ${next.before.length} control points and the curve ${next.points.length}; the current curve is now the "before" one`,
      );
    }
    next = { ...next, before: copy(next.points) };
  }
  if (next.repeated >= next.points.length) {
    issues.push(`there is no P${next.repeated} to repeat; P1 is repeated instead`);
    next = { ...next, repeated: Math.min(1, next.points.length - 1) };
  }
  return { state: next, issues };
}
