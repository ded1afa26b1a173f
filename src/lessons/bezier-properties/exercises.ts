import type { ExerciseSpec } from '../../kit/exercise';
import { closedPoint, closedSmooth } from './closed/exercises';
import { inflection } from './cubic/exercise';
import { localMove } from './local/exercise';
import type { PropertiesState } from './state';

// The lesson's exercises, each in the folder of the experiment it practises
// (local, closed, cubic), listed here in the order of the properties.

/** The Bézier properties lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<PropertiesState>[] = [
  localMove,
  closedPoint,
  closedSmooth,
  inflection,
];
