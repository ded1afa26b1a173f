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
import {
  type BumpReveal,
  type FlatReveal,
  type SaddleReveal,
  type TwistedReveal,
  type WaveReveal,
  bumpScript,
  flatScript,
  saddleScript,
  twistedScript,
  waveScript,
} from './presetScripts';
import type { SurfaceMode, SurfaceState } from './state';

/** The nets worth seeing, each a scene with steps of its own. */
export type Preset = 'flat' | 'saddle' | 'bump' | 'wave' | 'twisted';

/** Every name a step of the lesson reveals, over all its scenes. */
export type Reveal =
  | PatchReveal
  | RowsReveal
  | CasteljauReveal
  | MatrixReveal
  | WeightsReveal
  | NormalReveal
  | JoinReveal
  | FlatReveal
  | SaddleReveal
  | BumpReveal
  | WaveReveal
  | TwistedReveal;

export type SurfaceScript = Script<SurfaceState, SurfaceModel, Reveal>;

/** The steps of each kind of scene (the state's `mode`); the nets worth seeing have their own (PRESET_SCRIPTS). */
export const SCRIPTS: Readonly<Record<SurfaceMode, SurfaceScript>> = {
  patch: patchScript,
  rows: rowsScript,
  casteljau: casteljauScript,
  matrix: matrixScript,
  weights: weightsScript,
  normal: normalScript,
  join: joinScript,
};

/** The steps of the nets worth seeing, each its own idea (mode `patch`, told apart by the net). */
export const PRESET_SCRIPTS: Readonly<Record<Preset, SurfaceScript>> = {
  flat: flatScript,
  saddle: saddleScript,
  bump: bumpScript,
  wave: waveScript,
  twisted: twistedScript,
};
