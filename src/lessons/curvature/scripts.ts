import type { Script } from '../../kit/script';
import { type ArcReveal, arcScript } from './arcScript';
import { type JoinsReveal, joinsScript } from './joinsScript';
import type { CurvatureModel } from './model';
import { type PlaneReveal, planeScript } from './planeScript';
import { type SpaceReveal, spaceScript } from './spaceScript';
import type { CurvatureState, Part } from './state';

/** Every name a step of the lesson reveals, over its parts. */
export type Reveal = PlaneReveal | SpaceReveal | ArcReveal | JoinsReveal;

export type LessonScript = Script<CurvatureState, CurvatureModel, Reveal>;

/** The steps of each part: every scene of a part walks the same steps. */
export const PART_SCRIPTS: Readonly<Record<Part, LessonScript>> = {
  plane: planeScript,
  space: spaceScript,
  arc: arcScript,
  joins: joinsScript,
};
