import type { ExerciseSpec } from '../../kit/exercise';
import { levelPoint } from './levelPointExercise';
import { splitHalf } from './splitHalfExercise';
import type { DeCasteljauState } from './state';
import { throughPoint } from './throughPointExercise';
import { whereIsPoint } from './whereIsPointExercise';

// The lesson's four exercises, each in a file of its own: predict P(t),
// compute a point of a level, split the curve, make it pass through X.

/** The de Casteljau lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<DeCasteljauState>[] = [
  whereIsPoint,
  levelPoint,
  splitHalf,
  throughPoint,
];
