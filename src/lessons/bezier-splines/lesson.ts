import { defineLesson } from '../../app/lesson';
import { mainFigure } from './figure';
import { gridFigures, gridLayout } from './gridFigures';
import { type BezierSplinesModel, derive } from './model';
import { bezierSplinesPanel } from './panel';
import { scenes, steps } from './script';
import { type BezierSplinesState, normalize, schema } from './state';

export default defineLesson<BezierSplinesState, BezierSplinesModel>({
  slug: 'bezier-splines',
  schema,
  derive,
  figures: [mainFigure, ...gridFigures],
  layout: { column: ['main', gridLayout] },
  steps,
  scenes,
  normalize,
  panel: bezierSplinesPanel,
});
