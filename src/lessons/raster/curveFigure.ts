import { count } from '../../app/fields';
import type { KitFigure } from '../../kit/lesson';
import type { Painter } from '../../render/painter';
import { boundsOf, unionBounds } from '../../render/projection';
import {
  drawCurve,
  drawGap,
  drawPolyline,
  fillPixels,
  heading,
  pixelGrid,
  pixelSquare,
} from './draw';
import { type RasterModel, SAME_ERROR_MAX } from './model';
import { controlPoints } from './points';
import { windowOf } from './raster';
import { zoomWords } from './zoomView';
import { RASTER_HEIGHT, RASTER_WIDTH, type RasterState } from './state';

const RASTER_BOX = boundsOf([
  [0, 0],
  [RASTER_WIDTH, RASTER_HEIGHT],
]);

function controlPolygon(painter: Painter, m: RasterModel): void {
  painter.polyline(m.state.points, {
    color: painter.theme.polygon,
    width: painter.theme.sizes.thin,
    dash: [6, 5],
  });
}

function drawPlot(painter: Painter, m: RasterModel, labels: boolean): void {
  const { shown } = m;
  const color = painter.color(0);
  controlPolygon(painter, m);
  if (shown.has('curve')) drawCurve(painter, m.curve);
  if (shown.has('polyline')) drawPolyline(painter, m.uniform.points, color);
  else if (shown.has('samples'))
    for (const p of m.uniform.points) painter.dot(p, color, painter.theme.sizes.point);
  if (shown.has('gap')) drawGap(painter, m.uniform, m.state.zoom, labels);
}

/**
 * Uniform sampling, on the left of the compare scene: the slider's n
 * segments; then as many as reach the adaptive polyline's gap (measured); at
 * the last step as many as the flatness bound plans for (not measured). The
 * heading counts the polyline drawn, as the caption does.
 */
function drawCompare(painter: Painter, m: RasterModel, labels: boolean): void {
  const { shown } = m;
  controlPolygon(painter, m);
  drawCurve(painter, m.curve);
  if (shown.has('bound')) {
    drawPolyline(painter, m.bound.points, painter.color(3));
    drawGap(painter, m.bound, m.state.zoom, labels);
    if (labels)
      heading(painter, `Uniform, planned: ${count(m.bound.points.length - 1, 'segment')}`);
    return;
  }
  const sameGap = shown.has('sameGap');
  if (sameGap && m.sameErrorBeyond) {
    // Not computed, so not drawn: the count is past the search's end.
    painter.note(`Uniform sampling needs more than ${SAME_ERROR_MAX} segments for the same gap.`);
    if (labels) heading(painter, `Uniform: more than ${SAME_ERROR_MAX} segments`);
    return;
  }
  const drawn = sameGap && m.sameError ? m.sameError : m.uniform;
  const uniform = shown.has('uniform');
  if (uniform) {
    drawPolyline(painter, drawn.points, painter.color(sameGap ? 2 : 0));
    drawGap(painter, drawn, m.state.zoom, labels);
  }
  if (labels)
    heading(
      painter,
      `Uniform: ${uniform ? count(drawn.points.length - 1, 'segment') : 'how many segments?'}`,
    );
}

function drawSubdivide(painter: Painter, m: RasterModel): void {
  const theme = painter.theme;
  const asking = m.shown.is('question');
  drawCurve(painter, m.curve, !asking);
  if (asking) controlPolygon(painter, m);
  for (const node of m.tree.slice(0, m.piecesShown)) {
    if (node.split) continue;
    drawPolyline(painter, [node.points[0], node.points[node.points.length - 1]], painter.color(0));
  }
  const current = m.shown.is('pieces') ? m.tree[m.piecesShown - 1] : null;
  if (current) {
    const color = current.split ? theme.accent : painter.color(2);
    painter.polyline(current.points, { color, width: theme.sizes.line * 1.2 });
    for (const p of current.points) painter.dot(p, color, theme.sizes.point * 0.7);
  }
}

function drawPixels(painter: Painter, m: RasterModel): void {
  const { size, line } = m;
  const theme = painter.theme;
  pixelGrid(painter, size);
  if (m.shown.has('everySegment'))
    fillPixels(painter, m.pixels.values(), size.zoom, theme.ink, 0.75);
  else {
    const lit = line.pixels.slice(0, m.pixelsShown).map(([i, j]) => ({ i, j, value: 1 }));
    fillPixels(painter, lit, size.zoom, theme.accent, 0.8);
    if (m.shown.has('ends')) {
      for (const [i, j] of [line.pixels[0], line.pixels[line.pixels.length - 1]])
        painter.polyline(
          pixelSquare(i, j, size.zoom),
          { color: theme.accent, width: theme.sizes.line },
          true,
        );
    }
  }
  drawCurve(painter, m.curve, true);
  painter.polyline(m.adaptive.points, { color: painter.color(0), width: theme.sizes.thin * 1.5 });
}

function drawCoverage(painter: Painter, m: RasterModel): void {
  const { size } = m;
  const theme = painter.theme;
  pixelGrid(painter, size);
  if (m.shown.has('shades') && m.coverage)
    fillPixels(painter, m.coverage.values(), size.zoom, theme.ink);
  else fillPixels(painter, m.pixels.values(), size.zoom, theme.ink, 0.35);
  const a = m.adaptive.points[m.segment];
  const b = m.adaptive.points[m.segment + 1];
  painter.segment(a, b, { color: painter.color(0), width: theme.sizes.line });
}

function drawZoom(painter: Painter, m: RasterModel, labels: boolean): void {
  const zoom = m.zoom;
  if (!zoom) return;
  const theme = painter.theme;
  const { size } = zoom;
  controlPolygon(painter, m);
  drawCurve(painter, m.curve);
  drawPolyline(painter, m.uniform.points, painter.color(0));
  // Where adaptive flattening would put its vertices at this zoom.
  for (const p of zoom.adaptive) painter.dot(p, painter.color(1), theme.sizes.point * 0.6);
  const { minX: x0, minY: y0, maxX: x1, maxY: y1 } = windowOf(size);
  painter.polyline(
    [
      [x0, y0],
      [x1, y0],
      [x1, y1],
      [x0, y1],
    ],
    { color: theme.accent, width: theme.sizes.line * 1.2 },
    true,
  );
  if (labels) heading(painter, `The box: 32 × 24 pixels at ×${zoomWords(size.zoom)}`);
}

/** What the curve figure draws in each scene. */
const DRAW: Record<
  RasterState['view'],
  (painter: Painter, m: RasterModel, labels: boolean) => void
> = {
  plot: drawPlot,
  compare: drawCompare,
  subdivide: drawSubdivide,
  pixels: drawPixels,
  coverage: drawCoverage,
  zoom: drawZoom,
};

export const curveFigure: KitFigure<RasterState, RasterModel> = {
  id: 'curve',
  title: 'The curve, the segments drawn for it, and the pixels they light',
  kind: 'geometry',
  weight: 1.25,
  // The zoom scene takes in its screen's box too: at ×½ the box is twice the
  // raster's size, and its heading named a box that was off the figure.
  bounds: (m) => {
    const shown = unionBounds(boundsOf(m.state.points), RASTER_BOX);
    return m.state.view === 'zoom' && m.zoom ? unionBounds(shown, windowOf(m.zoom.size)) : shown;
  },
  // The comparison and the zoom write what they show along the top.
  headline: (m) => m.state.view === 'compare' || m.state.view === 'zoom',
  draw(painter, m, info) {
    const labels = !info.thumbnail;
    if (m.oneSpot)
      painter.note(
        'All control points are on one spot: the curve is that single point, so every segment has length 0 and covers at most one pixel.',
      );
    DRAW[m.state.view](painter, m, labels);
  },
  points: [controlPoints],
  addTo: controlPoints,
};
