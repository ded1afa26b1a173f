import { defineLesson } from '../../kit/lesson';
import { exercises } from './exercises';
import { constructionFigure } from './figure';
import { derive } from './model';
import { deCasteljauPanel } from './panel';
import { SCENES, sceneOf } from './scenes';
import { constructionTables } from './tables';
import { schema } from './state';
import { SCRIPTS } from './walks';

export default defineLesson({
  slug: 'de-casteljau',
  letter: 't',
  schema,
  step: 'step',
  script: SCRIPTS.construction,
  // The pseudocode and the expansion walk steps of their own; the state's mode says which.
  sceneOf,
  derive,
  figures: [constructionFigure],
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  scenes: SCENES,
  panel: deCasteljauPanel,
  tables: constructionTables,
  exercises,
});
