import type { Script } from '../../kit/script';
import {
  type CasteljauReveal,
  type PatchReveal,
  type RowsReveal,
  casteljauScript,
  patchScript,
  rowsScript,
} from './constructionScripts';
import type { SurfaceModel } from './model';
import {
  type JoinReveal,
  type MatrixReveal,
  type NormalReveal,
  type WeightsReveal,
  joinScript,
  matrixScript,
  normalScript,
  weightsScript,
} from './propertyScripts';
import type { SurfaceMode, SurfaceState } from './state';

/** Every name a step of the lesson reveals, over all its scenes. */
export type Reveal =
  | PatchReveal
  | RowsReveal
  | CasteljauReveal
  | MatrixReveal
  | WeightsReveal
  | NormalReveal
  | JoinReveal;

export type SurfaceScript = Script<SurfaceState, SurfaceModel, Reveal>;

/** The steps of each kind of scene (the state's `mode`). */
export const SCRIPTS: Readonly<Record<SurfaceMode, SurfaceScript>> = {
  patch: patchScript,
  rows: rowsScript,
  casteljau: casteljauScript,
  matrix: matrixScript,
  weights: weightsScript,
  normal: normalScript,
  join: joinScript,
};

/** What the steps so far reveal in this state. */
export const shownIn = (state: SurfaceState) => SCRIPTS[state.mode].shown(state, state.step);
