import { dataTable, fmt, h, liveText, setDisabled, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { rangeField } from '../../app/rangeControls';
import { notesKey, notesSlip } from '../../kit/notes';
import { formula } from '../../render/formula';
import { type RasterModel, SAME_ERROR_MAX } from './model';
import { controlPoints } from './points';
import { HAIRPIN, type RasterState, ZOOM_MAX, ZOOM_MIN, segmentsOf } from './state';
import { gestures } from '../../kit/gestures';

const INTRO = `A screen cannot draw a curve. It draws straight segments between points computed on the curve, and each segment as a row of pixels. How many segments, and where? The control points are given in pixels of a coarse 32 × 24 raster (zoom 1); to move one, ${gestures().move}; to add one, ${gestures().add}; to remove one, ${gestures().remove}.`;

/**
 * The “Splines” slides, where they pose the raster conversion problem, swap
 * the two words for what a spline does with its points.
 */
const splineSlip = () =>
  notesSlip(
    'spline slides',
    'that a spline which interpolates its control points need not pass through them, and one which approximates them does',
    'It is the other way round: an interpolating curve passes through its points, an approximating one is only pulled towards them. The Bézier curve here approximates its control points: it passes through the first and the last only.',
  );

/** The slides' symbols beside the lesson's. */
const slideSymbols = () =>
  notesKey([
    [
      'P₀ … Pₙ, the control points',
      'p₀ … pₙ, pₖ = (xₖ, yₖ), in the “Splines” slides, which also call them knots',
    ],
    [
      'the segments of the polyline',
      'the “short line segments” that ink the computed points into a curve, in the “Splines” slides',
    ],
  ]);

export function rasterPanel(
  api: LessonApi<RasterState, RasterModel>,
): LessonPanel<RasterState, RasterModel> {
  const button = (label: string, action: () => void) =>
    h('button', { type: 'button', onclick: action }, label);
  const change = (f: (s: RasterState) => Partial<RasterState>) => {
    const s = api.get();
    api.set({ ...s, ...f(s) });
  };

  const tolerance = rangeField(api, {
    label: 'Tolerance τ in pixels',
    name: 'τ',
    min: 0.05,
    max: 2,
    step: 0.05,
    get: (s) => s.tolerance,
    set: (s, value) => ({ ...s, tolerance: value }),
    coalesce: 'raster-tol',
    readout: true,
  });
  const zoomText = h('span', {});
  const zoomOut = button('Zoom out ÷2', () =>
    change((s) => ({ zoom: Math.max(ZOOM_MIN, s.zoom / 2) })),
  );
  const zoomIn = button('Zoom in ×2', () =>
    change((s) => ({ zoom: Math.min(ZOOM_MAX, s.zoom * 2) })),
  );
  const zoomBox = h('div', { class: 'lesson-tools' }, zoomOut, zoomText, zoomIn);
  const previous = button('◀ Previous segment', () =>
    change((s) => ({ steppedSegment: Math.max(0, s.steppedSegment - 1), step: 0 })),
  );
  const next = button('Next segment ▶', () =>
    change((s) => ({ steppedSegment: s.steppedSegment + 1, step: 0 })),
  );
  const segmentText = liveText(h('span', {}));
  const segmentBox = h('div', { class: 'lesson-tools' }, previous, segmentText, next);
  const pointCount = controlPoints.buttons(api);
  const reset = button('The hairpin again', () =>
    change(() => ({ points: HAIRPIN.map((p) => [...p]) })),
  );

  const compareBody = h('tbody', {});
  const compareRows = new LiveRows(compareBody);
  const segmentTitle = h('p', {});
  const pixelBody = h('tbody', {});
  const pixelRows = new LiveRows(pixelBody);
  const pixelSection = h(
    'div',
    {},
    h('h2', {}, 'One segment, pixel by pixel'),
    segmentTitle,
    dataTable('Pixels of the segment', ['Step', 'Pixel x', 'Pixel y', 'Ideal'], pixelBody),
  );

  const element = h(
    'div',
    { class: 'lesson-text' },
    h('p', {}, INTRO),
    splineSlip(),
    slideSymbols(),
    h(
      'p',
      { class: 'note' },
      'The slider n under the figure is the number of uniform segments: the parameter values t = k/n, k = 0 … n.',
    ),
    h('h2', {}, 'Uniform against adaptive'),
    h(
      'p',
      {},
      'Adaptive flattening splits the curve at t = ½ (de Casteljau, as in the de Casteljau lesson) until each piece’s control polygon is flat enough: a piece of degree n lies within n(n−1)/8 · max‖Δ²P‖ of its chord.',
    ),
    formula('\\tfrac{n(n-1)}{8}\\,\\max_i \\|P_{i+2} - 2P_{i+1} + P_i\\| \\le \\tau', true),
    tolerance.element,
    dataTable(
      'Uniform against adaptive',
      ['Polyline', 'Segments', 'Largest gap (px)', 'at t'],
      compareBody,
      'names',
    ),
    h('h2', {}, 'The raster'),
    h(
      'p',
      {},
      'Zoom z: z pixels per unit, so the raster is 32z × 24z pixels and a tolerance of τ pixels is τ/z units. Zoom in and a fixed polyline strays more pixels; adaptive flattening adds segments, about √2 times as many each time the zoom doubles.',
    ),
    zoomBox,
    segmentBox,
    pixelSection,
    h('h2', {}, 'The curve'),
    pointCount.element,
    h('div', { class: 'lesson-tools' }, reset),
  );

  return {
    element,
    update(m, state) {
      pointCount.update(state);
      tolerance.update(state, `= ${fmt(state.tolerance, 2)} px`);
      setText(zoomText, `zoom ×${state.zoom} (${m.size.width} × ${m.size.height} pixels)`);
      setDisabled(zoomOut, state.zoom <= ZOOM_MIN);
      setDisabled(zoomIn, state.zoom >= ZOOM_MAX);
      const segments = m.adaptive.points.length - 1;
      setText(segmentText, `segment ${m.segment + 1} of ${segments}`);
      setDisabled(previous, m.segment <= 0);
      setDisabled(next, m.segment >= segments - 1);

      const { zoom } = state;
      const row = (name: string, line: RasterModel['uniform'], key: string) => ({
        data: {
          polyline: key,
          segments: String(line.points.length - 1),
          gap: String(line.deviation.distance * zoom),
        },
        cells: [
          name,
          String(line.points.length - 1),
          fmt(line.deviation.distance * zoom, 4),
          fmt(line.deviation.t, 4),
        ],
      });
      compareRows.set([
        row(`Uniform, n = ${segmentsOf(state)}`, m.uniform, 'uniform'),
        row(`Adaptive, τ = ${fmt(state.tolerance, 2)} px`, m.adaptive, 'adaptive'),
        ...(m.sameError ? [row('Uniform, same gap as adaptive', m.sameError, 'same')] : []),
        ...(m.sameErrorBeyond
          ? [
              {
                data: { polyline: 'same', segments: '', gap: '' },
                cells: [
                  'Uniform, same gap as adaptive',
                  `more than ${SAME_ERROR_MAX}`,
                  `≤ ${fmt(m.adaptive.deviation.distance * zoom, 4)}`,
                  '—',
                ],
              },
            ]
          : []),
        row('Uniform, planned for τ by the bound', m.bound, 'bound'),
      ]);

      const pixelScene = state.view === 'pixels' || state.view === 'coverage';
      setHidden(segmentBox, !pixelScene);
      setHidden(pixelSection, !pixelScene);
      if (pixelScene) {
        const { line } = m;
        const [u0, v0] = line.from;
        const [u1, v1] = line.to;
        segmentTitle.dataset.from = `${u0},${v0}`;
        segmentTitle.dataset.to = `${u1},${v1}`;
        const listed =
          line.count > line.pixels.length
            ? ` It lights ${line.count} pixels; the table lists the first ${line.pixels.length}.`
            : '';
        setText(
          segmentTitle,
          `Segment ${m.segment + 1} runs from (${fmt(u0, 3)}, ${fmt(v0, 3)}) to (${fmt(u1, 3)}, ${fmt(v1, 3)}) in pixel coordinates (pixel centres at whole numbers). It steps along ${line.major}: one pixel per step, the nearest across.${listed}`,
        );
        pixelRows.set(
          line.pixels.map(([i, j], k) => ({
            cells: [String(k), String(i), String(j), fmt(line.ideal[k], 3)],
          })),
        );
      }
    },
  };
}
