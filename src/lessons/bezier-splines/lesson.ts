import { defineLesson } from '../../kit/lesson';
import { exercises } from './exercises';
import { mainFigure } from './figure';
import { gridFigures, gridLayout } from './gridFigures';
import { derive } from './model';
import { bezierSplinesPanel } from './panel';
import { scenes } from './scenes';
import { normalize, schema } from './state';

export default defineLesson({
  slug: 'bezier-splines',
  letter: 't',
  schema,
  step: 'step',
  // Each part is a scene with its own steps and figures: the state's part says which.
  sceneOf: (state) => state.part,
  derive,
  scenes,
  figures: [mainFigure, ...gridFigures],
  layout: { column: ['main', gridLayout] },
  normalize,
  panel: bezierSplinesPanel,
  exercises,
});
