import { count } from '../../app/fields';
import { texNumber } from '../../kit/format';
import type { KitFigure } from '../../kit/lesson';
import type { Painter } from '../../render/painter';
import { type Bounds, boundsOf, unionBounds } from '../../render/projection';
import { drawCurve, drawGap, drawPolyline, fillPixels, heading, pixelGrid } from './draw';
import { drawMagnifier, magnifierBounds } from './magnifier';
import type { RasterModel } from './model';
import { windowOf } from './raster';
import { drawTree, treeBounds } from './tree';
import { zoomWords } from './zoomView';
import { RASTER_HEIGHT, RASTER_WIDTH, type RasterState } from './state';

// The figure beside the curve: the gap over t (plot), the adaptive polyline
// (compare), the recursion tree (subdivide), one segment magnified (pixels,
// coverage), the adaptive raster (zoom).

/** Width of the t axis and height of the tallest arch of the gap plot, in its units. */
const T_WIDTH = 32;
const GAP_HEIGHT = 14;

const curveBounds = (m: RasterModel) =>
  unionBounds(
    boundsOf(m.state.points),
    boundsOf([
      [0, 0],
      [RASTER_WIDTH, RASTER_HEIGHT],
    ]),
  );

const gapScale = (m: RasterModel) => GAP_HEIGHT / Math.max(1e-9, m.uniform.deviation.distance);

function drawGapPlot(painter: Painter, m: RasterModel, labels: boolean): void {
  const theme = painter.theme;
  const { shown } = m;
  const scale = gapScale(m);
  painter.segment([0, 0], [T_WIDTH, 0], { color: theme.axis, width: theme.sizes.thin * 1.5 });
  const small = {
    size: theme.sizes.small,
    color: theme.muted,
    align: 'center' as const,
    halo: true,
  };
  for (const t of [0, 0.25, 0.5, 0.75, 1]) {
    painter.segment([T_WIDTH * t, 0], [T_WIDTH * t, -0.6], { color: theme.axis, width: 1 });
    if (labels)
      painter.label(String(t), [T_WIDTH * t, -0.6], { ...small, dy: theme.sizes.small * 1.1 });
  }
  if (labels)
    heading(painter, shown.has('curve') ? 'The gap to the curve over t' : 'The parameter t');
  if (shown.has('samples')) {
    for (const t of m.uniform.parameters)
      painter.dot([T_WIDTH * t, 0], painter.color(0), theme.sizes.point);
  }
  if (!shown.has('curve') || !m.gaps) return;
  const arches = new Float64Array(m.gaps.length);
  for (let i = 0; i < m.gaps.length; i += 2) {
    arches[i] = T_WIDTH * m.gaps[i];
    arches[i + 1] = scale * m.gaps[i + 1];
  }
  painter.polylineFlat(arches, { color: theme.accent, width: theme.sizes.line * 1.3 });
  if (!shown.has('gap')) return;
  const { t, distance } = m.uniform.deviation;
  const top = [T_WIDTH * t, scale * distance];
  painter.segment([T_WIDTH * t, 0], top, {
    color: theme.accent,
    width: theme.sizes.thin,
    dash: [5, 4],
  });
  painter.ring(top, theme.sizes.point * 1.8, { color: theme.accent, width: theme.sizes.line });
  if (labels)
    painter.label(`${(distance * m.state.zoom).toFixed(2)} px at t = ${t.toFixed(3)}`, top, {
      dy: -theme.sizes.label,
      align: 'center',
      color: theme.accent,
      halo: true,
      bold: true,
    });
}

function drawAdaptive(painter: Painter, m: RasterModel, labels: boolean): void {
  const theme = painter.theme;
  const { points, tolerance, zoom } = m.state;
  const adaptive = m.shown.has('adaptive');
  painter.polyline(points, { color: theme.polygon, width: theme.sizes.thin, dash: [6, 5] });
  for (const p of points) painter.dot(p, theme.polygon, theme.sizes.point * 0.6);
  drawCurve(painter, m.curve);
  if (adaptive) {
    drawPolyline(painter, m.adaptive.points, painter.color(1));
    drawGap(painter, m.adaptive, zoom, labels);
  }
  if (labels)
    heading(
      painter,
      `Adaptive, τ = ${texNumber(tolerance, 2)} px: ${adaptive ? count(m.adaptive.points.length - 1, 'segment') : 'how many segments?'}`,
    );
}

function drawZoomWindow(painter: Painter, m: RasterModel, labels: boolean): void {
  const zoom = m.zoom;
  if (!zoom) return;
  const theme = painter.theme;
  pixelGrid(painter, zoom.size);
  fillPixels(painter, zoom.uniformPixels.values(), zoom.size.zoom, theme.ink, 0.55);
  fillPixels(painter, zoom.uniformFar, zoom.size.zoom, theme.accent, 0.85);
  drawCurve(painter, m.curve);
  painter.polyline(m.uniform.points, { color: painter.color(0), width: theme.sizes.line });
  if (labels) {
    const gap = m.uniform.deviation.distance * zoom.size.zoom;
    heading(
      painter,
      `×${zoomWords(zoom.size.zoom)}: ${count(m.uniform.points.length - 1, 'segment')} ${gap.toFixed(2)} px off, ${count(zoom.uniformFar.length, 'pixel')} wrong`,
    );
  }
}

function sideBounds(m: RasterModel): Bounds {
  switch (m.state.view) {
    case 'plot':
      return { minX: -1.5, maxX: T_WIDTH + 1.5, minY: -3, maxY: GAP_HEIGHT + 4 };
    case 'subdivide':
      return treeBounds(m);
    case 'pixels':
    case 'coverage':
      return magnifierBounds(m);
    case 'zoom':
      return m.zoom ? windowOf(m.zoom.size) : curveBounds(m);
    default:
      return curveBounds(m);
  }
}

export const sideFigure: KitFigure<RasterState, RasterModel> = {
  id: 'side',
  title:
    'Beside the curve: the gap over t, adaptive flattening, its recursion tree, one segment magnified',
  kind: 'drawing',
  bounds: sideBounds,
  draw(painter, m, info) {
    const labels = !info.thumbnail;
    switch (m.state.view) {
      case 'plot':
        return drawGapPlot(painter, m, labels);
      case 'compare':
        return drawAdaptive(painter, m, labels);
      case 'subdivide':
        drawTree(painter, m, labels);
        if (labels) heading(painter, 'The recursion tree');
        return;
      case 'pixels':
      case 'coverage':
        drawMagnifier(painter, m, labels);
        if (labels) heading(painter, `Segment ${m.segment + 1}, magnified`);
        return;
      case 'zoom':
        return drawZoomWindow(painter, m, labels);
    }
  },
};
