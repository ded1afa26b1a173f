import { defineLesson } from '../../app/lesson';
import { propertiesFigure } from './figure';
import { type PropertiesModel, derive } from './model';
import { propertiesPanel } from './panel';
import { PRESETS } from './presets';
import { describeStep, stepFormula } from './script';
import { type PropertiesState, normalize, schema, stepCount } from './state';

export default defineLesson<PropertiesState, PropertiesModel>({
  slug: 'bezier-properties',
  schema,
  derive,
  figures: [propertiesFigure],
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  steps: { key: 'k', count: stepCount, describe: describeStep, formula: stepFormula },
  scenes: PRESETS,
  normalize,
  panel: propertiesPanel,
});
