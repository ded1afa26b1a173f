import { type ExerciseSpec, pointTask, random } from '../../kit/exercise';
import { words } from '../../kit/format';
import { bezierPoint } from '../../math';
import { FRIENDLY_T, arch, polygonOnly, walked } from './exerciseSetup';
import type { DeCasteljauState } from './state';

// The first exercise: guess where P(t) lands before the construction is walked.

/** Predict P(t): guess where the construction's last point lands. */
export const whereIsPoint: ExerciseSpec<DeCasteljauState> = {
  id: 'where-is-p',
  title: 'Where is P(t)?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const degree = r.pick([2, 3] as const);
    const p = arch(r, degree);
    const t = r.pick(FRIENDLY_T);
    const answer = bezierPoint(p, t);
    const tolerance = 0.2;
    const cuts = degree === 3 ? 'then once more' : 'then';
    return {
      state: polygonOnly(defaults, p, t),
      prompt: `Where is P(${words(t)}) on the Bézier curve of this control polygon? Tap your guess; within ${words(tolerance)} of the point counts.`,
      task: pointTask(
        'construction',
        answer,
        tolerance,
        `Level 1 cuts every edge at t = ${words(t)} from its first end, level 2 cuts the new edges, ${cuts}: the last point is P(t).`,
      ),
      working: walked(defaults, p, t),
    };
  },
};
