import { defineLesson } from '../../app/lesson';
import { mapFigure } from './figure';
import { type RoadModel, derive } from './model';
import { roadPanel } from './panel';
import { presets } from './presets';
import { describeStep, roadFormula } from './script';
import { type RoadState, normalize, schema, stepCount } from './state';

export default defineLesson<RoadState, RoadModel>({
  slug: 'road',
  schema,
  derive,
  figures: [mapFigure],
  steps: { key: 'step', count: stepCount, describe: describeStep, formula: roadFormula },
  normalize,
  scenes: presets,
  panel: roadPanel,
});
