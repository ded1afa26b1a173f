import { defineLesson } from '../../kit/lesson';
import { exercises } from './exercises';
import { propertiesFigure } from './figure';
import { derive } from './model';
import { propertiesPanel } from './panel';
import { SCENES, sceneOf } from './scenes';
import { normalize, schema } from './state';

export default defineLesson({
  slug: 'bezier-properties',
  letter: 't',
  schema,
  step: 'step',
  // Each scene walks its experiment's steps; the state's experiment says which scene it is in.
  sceneOf,
  derive,
  figures: [propertiesFigure],
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  scenes: SCENES,
  normalize,
  panel: propertiesPanel,
  exercises,
});
