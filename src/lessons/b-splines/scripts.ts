import type { Script } from '../../kit/script';
import {
  type ConvertReveal,
  type LocalReveal,
  type PropertiesReveal,
  convertScript,
  localScript,
  propertiesScript,
} from './cubicScripts';
import { type ContinuityReveal, continuityScript } from './continuityScript';
import { type KnotReveal, knotScript } from './knotScript';
import { type MeaningsReveal, meaningsScript } from './meaningsScript';
import type { BSplineModel } from './model';
import {
  type CircleReveal,
  type NurbsReveal,
  type ProjectiveReveal,
  circleScript,
  nurbsScript,
  projectiveScript,
} from './nurbsScripts';
import { type BSplineState, FAMILY, type Family, type Part } from './state';
import { type UniformReveal, uniformScript } from './uniformScript';

/** Every name a step of the lesson reveals, over all its scene families. */
export type Reveal =
  | UniformReveal
  | LocalReveal
  | ConvertReveal
  | PropertiesReveal
  | KnotReveal
  | NurbsReveal
  | CircleReveal
  | ProjectiveReveal
  | MeaningsReveal
  | ContinuityReveal;

export type LessonScript = Script<BSplineState, BSplineModel, Reveal>;

/**
 * A family's script on the lesson's model. Each family's steps read its own
 * model (a LocalModel, a KnotModel, …) while the kit types one model per
 * lesson; this is sound because `derive` picks the model's kind from the same
 * `part` of the state that picks the script: a script only ever sees its own kind.
 */
const onLesson = <M extends BSplineModel, N extends Reveal>(
  script: Script<BSplineState, M, N>,
): LessonScript => script as unknown as LessonScript;

/** The steps of each scene family. */
export const SCRIPTS: Readonly<Record<Family, LessonScript>> = {
  uniform: onLesson(uniformScript),
  local: onLesson(localScript),
  convert: onLesson(convertScript),
  properties: onLesson(propertiesScript),
  knots: onLesson(knotScript),
  nurbs: onLesson(nurbsScript),
  circle: onLesson(circleScript),
  projective: onLesson(projectiveScript),
  meanings: onLesson(meaningsScript),
  continuity: onLesson(continuityScript),
};

/** The steps of a part's scene: its family's. */
export const partScript = (part: Part): LessonScript => SCRIPTS[FAMILY[part]];

/** The script of the scene a state is in. */
export const scriptOf = (state: BSplineState): LessonScript => partScript(state.part);
