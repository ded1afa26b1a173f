import { defineLesson } from '../../app/lesson';
import { basisFigure } from './basisFigure';
import { curveFigure } from './curveFigure';
import { knotFigure } from './knotFigure';
import { type BSplineModel, derive } from './model';
import { bsplinePanel } from './panel';
import { SCENES } from './scenes';
import { type BSplineState, normalize, schema } from './state';
import { steps } from './steps';

export default defineLesson<BSplineState, BSplineModel>({
  slug: 'b-splines',
  schema,
  derive,
  normalize,
  figures: [curveFigure, basisFigure, knotFigure],
  // The curve beside the basis plot and its knot strip: stacked, three figures leave
  // the presenter's large type no room to plot in.
  layout: { row: ['curve', { column: ['basis', 'knots'] }], weights: [1.8, 1] },
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.005 },
  steps,
  scenes: SCENES,
  panel: bsplinePanel,
});
