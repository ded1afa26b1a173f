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
  layout: 'column',
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.005 },
  steps,
  scenes: SCENES,
  panel: bsplinePanel,
});
