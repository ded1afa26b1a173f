import type { Point } from '../../math';
import { type AffineModel, deriveAffine } from './affine/model';
import { type ClosedModel, deriveClosed } from './closed/model';
import { type CubicModel, deriveCubic } from './cubic/model';
import { type ElevateModel, deriveElevate } from './elevate/model';
import { type EndsModel, deriveEnds } from './ends/model';
import { type HermiteModel, deriveHermite } from './hermite/model';
import { type HullModel, deriveHull } from './hull/model';
import { type LocalModel, deriveLocal } from './local/model';
import { type RepeatModel, deriveRepeat } from './repeat/model';
import { type SplitModel, deriveSplit } from './split/model';
import type { ExperimentId, PropertiesState } from './state';

/** One experiment's part of the model, told apart by `x`. */
export type ExperimentModel =
  | EndsModel
  | HullModel
  | LocalModel
  | RepeatModel
  | ClosedModel
  | ElevateModel
  | SplitModel
  | AffineModel
  | CubicModel
  | HermiteModel;

/** Everything the figure and the panel show, computed once per state. */
export type PropertiesModel = {
  state: PropertiesState;
  /** What "fit view" shows: the control points, the curve's own, and the experiment's extras. */
  extent: Point[];
} & ExperimentModel;

/** The model while experiment X is shown. */
export type ModelOf<X extends ExperimentId> = Extract<PropertiesModel, { x: X }>;

/** Each experiment's own derive: the registry pairs every id with the model of that experiment. */
const PARTS: {
  [X in ExperimentId]: (state: PropertiesState) => Extract<ExperimentModel, { x: X }>;
} = {
  ends: deriveEnds,
  hull: deriveHull,
  local: deriveLocal,
  repeat: deriveRepeat,
  closed: deriveClosed,
  elevate: deriveElevate,
  split: deriveSplit,
  affine: deriveAffine,
  cubic: deriveCubic,
  hermite: deriveHermite,
};

export function derive(state: PropertiesState): PropertiesModel {
  const part = PARTS[state.x](state);
  return { state, ...part, extent: [...state.p, ...part.controls, ...part.extra] };
}
