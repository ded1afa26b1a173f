import { triangleTables } from './tables';
import { defineLesson } from '../../kit/lesson';
import { basisFigure } from './basisFigure';
import { curveFigure } from './curveFigure';
import { knotFigure } from './knotFigure';
import { exercises } from './exercises';
import { derive } from './model';
import { bsplinePanel } from './panel';
import { SCENES } from './scenes';
import { normalize, schema } from './state';

export default defineLesson({
  slug: 'b-splines',
  schema,
  step: 'step',
  // Each scene has its family's steps; the state's part says which scene it is in.
  sceneOf: (state) => state.part,
  derive,
  normalize,
  figures: [curveFigure, basisFigure, knotFigure],
  // The curve beside the basis plot and its knot strip: stacked, three figures leave
  // the presenter's large type no room to plot in.
  layout: { row: ['curve', { column: ['basis', 'knots'] }], weights: [1.8, 1] },
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.005 },
  scenes: SCENES,
  panel: bsplinePanel,
  tables: triangleTables,
  exercises,
});
