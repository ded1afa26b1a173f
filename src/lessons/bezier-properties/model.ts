import type { Revealed } from '../../kit/script';
import type { Point } from '../../math';
import { type AffineModel, deriveAffine } from './affine/model';
import type { AffineReveal } from './affine/script';
import { type ClosedModel, deriveClosed } from './closed/model';
import type { ClosedReveal } from './closed/script';
import { type CubicModel, deriveCubic } from './cubic/model';
import type { CubicReveal } from './cubic/script';
import { type ElevateModel, deriveElevate } from './elevate/model';
import type { ElevateReveal } from './elevate/script';
import { type EndsModel, deriveEnds } from './ends/model';
import type { EndsReveal } from './ends/script';
import { type HermiteModel, deriveHermite } from './hermite/model';
import type { HermiteReveal } from './hermite/script';
import { type HodographModel, deriveHodograph } from './hodograph/model';
import type { HodographReveal } from './hodograph/script';
import { type HullModel, deriveHull } from './hull/model';
import type { HullReveal } from './hull/script';
import { type LocalModel, deriveLocal } from './local/model';
import type { LocalReveal } from './local/script';
import { type RepeatModel, deriveRepeat } from './repeat/model';
import type { RepeatReveal } from './repeat/script';
import { type SplitModel, deriveSplit } from './split/model';
import type { SplitReveal } from './split/script';
import type { ExperimentId, PropertiesState } from './state';

/** An experiment's model as the figure and the panel get it: its state, what its steps reveal, its view. */
type Shown<P, N extends string> = P & {
  state: PropertiesState;
  shown: Revealed<N>;
  /** What "fit view" shows: the control points, the curve's own, and the experiment's extras. */
  extent: Point[];
};

/** Everything the figure and the panel show, computed once per state: one kind per experiment. */
export type PropertiesModel =
  | Shown<EndsModel, EndsReveal>
  | Shown<HullModel, HullReveal>
  | Shown<LocalModel, LocalReveal>
  | Shown<RepeatModel, RepeatReveal>
  | Shown<ClosedModel, ClosedReveal>
  | Shown<ElevateModel, ElevateReveal>
  | Shown<SplitModel, SplitReveal>
  | Shown<AffineModel, AffineReveal>
  | Shown<CubicModel, CubicReveal>
  | Shown<HermiteModel, HermiteReveal>
  | Shown<HodographModel, HodographReveal>;

/** Every name a step of the lesson reveals, over all its experiments. */
export type Reveal =
  | EndsReveal
  | HullReveal
  | LocalReveal
  | RepeatReveal
  | ClosedReveal
  | ElevateReveal
  | SplitReveal
  | AffineReveal
  | CubicReveal
  | HermiteReveal
  | HodographReveal;

/** The model while experiment X is shown. */
export type ModelOf<X extends ExperimentId> = Extract<PropertiesModel, { kind: X }>;

/**
 * Each experiment's own geometry (memoised on the fields it reads, so a step
 * costs no new curve), and for elevation, subdivision and the repeated point
 * how many elevations, splits or copies the steps so far show.
 */
const PARTS: {
  [X in ExperimentId]: (
    state: PropertiesState,
    shown: Revealed<never>,
  ) => Omit<ModelOf<X>, 'state' | 'shown' | 'extent'>;
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
  hodograph: deriveHodograph,
};

export function derive(state: PropertiesState, shown: Revealed<Reveal>): PropertiesModel {
  // `shown` comes from the experiment's own script (scripts.ts): its names are the experiment's.
  const named = shown as Revealed<never>;
  const part = PARTS[state.experiment](state, named);
  const extent = [...state.points, ...part.controls, ...part.extra];
  return { ...part, state, shown: named, extent } as PropertiesModel;
}
