import type { Script } from '../../kit/script';
import { affineScript } from './affine/script';
import { closedScript } from './closed/script';
import { cubicScript } from './cubic/script';
import { elevateScript } from './elevate/script';
import { endsScript } from './ends/script';
import { hermiteScript } from './hermite/script';
import { hodographScript } from './hodograph/script';
import { hullScript } from './hull/script';
import { localScript } from './local/script';
import type { PropertiesModel, Reveal } from './model';
import { repeatScript } from './repeat/script';
import { splitScript } from './split/script';
import type { ExperimentId, PropertiesState } from './state';

export type LessonScript = Script<PropertiesState, PropertiesModel, Reveal>;

/**
 * An experiment's script on the lesson's model. Each experiment's steps read
 * its own model while the kit types one model per lesson; this is sound
 * because `derive` picks the model's kind from the same `experiment` field of
 * the state that picks the script: a script only ever sees its own kind.
 */
const onLesson = <M extends PropertiesModel, N extends Reveal>(
  script: Script<PropertiesState, M, N>,
): LessonScript => script as unknown as LessonScript;

/** The steps of each experiment. */
export const SCRIPTS: Readonly<Record<ExperimentId, LessonScript>> = {
  ends: onLesson(endsScript),
  hull: onLesson(hullScript),
  local: onLesson(localScript),
  repeat: onLesson(repeatScript),
  closed: onLesson(closedScript),
  elevate: onLesson(elevateScript),
  split: onLesson(splitScript),
  affine: onLesson(affineScript),
  cubic: onLesson(cubicScript),
  hermite: onLesson(hermiteScript),
  hodograph: onLesson(hodographScript),
};

/** The script of the experiment a state is in. */
export const scriptOf = (state: PropertiesState): LessonScript => SCRIPTS[state.experiment];
