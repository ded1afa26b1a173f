import { defineLesson } from '../../app/lesson';
import { curveFigure } from './curveFigure';
import { sideFigure } from './sideFigure';
import { type RasterModel, derive } from './model';
import { rasterPanel } from './panel';
import { scenes, steps } from './script';
import { type RasterState, schema } from './state';

export default defineLesson<RasterState, RasterModel>({
  slug: 'raster',
  schema,
  derive,
  figures: [curveFigure, sideFigure],
  layout: 'row',
  parameter: { key: 'n', label: 'n', min: 1, max: 64, step: 1 },
  steps,
  scenes,
  normalize(state) {
    // The segment stepped through must exist on the current polyline (the
    // model of this state, derived once: the shell asks for the same one).
    const segments = derive(state).adaptive.points.length - 1;
    const next = state.seg > segments - 1 ? { ...state, seg: segments - 1 } : state;
    return { state: next, issues: [] };
  },
  panel: rasterPanel,
});
