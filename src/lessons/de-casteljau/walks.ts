import type { Script } from '../../kit/script';
import { type BernsteinReveal, bernsteinForm } from './bernsteinForm';
import type { DeCasteljauModel } from './model';
import { type PseudocodeReveal, pseudocode } from './pseudocode';
import { type ConstructionReveal, construction } from './script';
import type { DeCasteljauState, Mode } from './state';

/** Every name a step of the lesson reveals, over its three walks. */
export type Reveal = ConstructionReveal | PseudocodeReveal | BernsteinReveal;

export type LessonScript = Script<DeCasteljauState, DeCasteljauModel, Reveal>;

/**
 * A walk's script on the lesson's names. Sound because the figure and the
 * panel ask a state's `shown` only for the names of its own mode's walk.
 */
const onLesson = <N extends Reveal>(walk: Script<DeCasteljauState, DeCasteljauModel, N>) =>
  walk as unknown as LessonScript;

/** The steps of each mode: the construction with or without its halves, the pseudocode, the expansion. */
export const SCRIPTS: Readonly<Record<Mode, LessonScript>> = {
  construction: onLesson(construction),
  halves: onLesson(construction),
  pseudocode: onLesson(pseudocode),
  bernstein: onLesson(bernsteinForm),
};

/** The script a state walks. */
export const scriptOf = (state: DeCasteljauState): LessonScript => SCRIPTS[state.mode];
