import { affine } from './affine';
import { cubic } from './cubic';
import { elevate } from './elevate';
import { ends } from './ends';
import type { Experiment } from './experiment';
import { hermite } from './hermite';
import { hull } from './hull';
import { local } from './local';
import { closed, repeat } from './repeat';
import { split } from './split';
import type { ExperimentId } from './state';

/** Every experiment, in the order of the lesson's list of properties. */
export const EXPERIMENTS: Record<ExperimentId, Experiment> = {
  ends,
  hull,
  local,
  repeat,
  closed,
  elevate,
  split,
  affine,
  cubic,
  hermite,
};

/** The number of the property an experiment shows (1 … 9), as the notes list them. */
export const PROPERTY_NUMBER: Record<ExperimentId, number> = {
  ends: 1,
  hull: 2,
  local: 3,
  repeat: 4,
  closed: 4,
  elevate: 5,
  split: 6,
  affine: 7,
  cubic: 8,
  hermite: 9,
};
