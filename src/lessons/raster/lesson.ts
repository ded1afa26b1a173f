import { defineLesson } from '../../kit/lesson';
import { exercises } from './exercises';
import type { Script } from '../../kit/script';
import { curveFigure } from './curveFigure';
import { compareScript, plotScript, subdivideScript } from './flatteningScripts';
import { flatteningOf } from './geometry';
import { type RasterModel, derive, instructiveSegment } from './model';
import { rasterPanel } from './panel';
import { coverageScript, pixelsScript, zoomScript } from './pixelScripts';
import type { Reveal } from './reveals';
import { sideFigure } from './sideFigure';
import { type RasterState, type View, schema } from './state';

/**
 * A scene sets what the figures show and the lecture's numbers; the curve
 * stays as it is. `change` then sets what the scene needs of its own.
 */
const scene = (
  id: View,
  label: string,
  script: Script<RasterState, RasterModel, Reveal>,
  change: (s: RasterState) => Partial<RasterState> = () => ({}),
) => ({
  id,
  label,
  script,
  setup: (current: RasterState): RasterState => {
    const next = { ...current, view: id, uniformSegments: 6, tolerance: 0.5, zoom: 1, step: 0 };
    return { ...next, ...change(next) };
  },
});

/** The segment worth stepping through: the most instructive of the adaptive polyline. */
const instructive = (s: RasterState) => ({
  steppedSegment: instructiveSegment(flatteningOf(s).adaptive.points, s.zoom),
});

export default defineLesson({
  slug: 'raster',
  letter: 't',
  schema,
  step: 'step',
  sceneOf: (state) => state.view,
  derive,
  figures: [curveFigure, sideFigure],
  layout: 'row',
  parameter: { key: 'uniformSegments', label: 'n', min: 1, max: 64, step: 1 },
  scenes: [
    scene('plot', 'Plot the curve', plotScript, () => ({ steppedSegment: 0 })),
    scene('compare', 'Uniform or adaptive', compareScript),
    scene('subdivide', 'Flatten by subdivision', subdivideScript),
    scene('pixels', 'Segments to pixels', pixelsScript, instructive),
    scene('coverage', 'Anti-aliasing', coverageScript, instructive),
    scene('zoom', 'Zoom in, zoom out', zoomScript, () => ({ uniformSegments: 4 })),
  ],
  normalize(state) {
    // The segment stepped through must exist on the current polyline.
    const segments = flatteningOf(state).adaptive.points.length - 1;
    const next =
      state.steppedSegment > segments - 1 ? { ...state, steppedSegment: segments - 1 } : state;
    return { state: next, issues: [] };
  },
  panel: rasterPanel,
  exercises,
});
