import type { FigureSpec } from '../../app/lesson';
import { insertPoint } from '../../interact/editPoints';
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
import { piecesShown, pixelsShown, stepCount } from './script';
import { MAX_POINTS, RASTER_HEIGHT, RASTER_WIDTH, type RasterState } from './state';

const RASTER_BOX = boundsOf([
  [0, 0],
  [RASTER_WIDTH, RASTER_HEIGHT],
]);

function controlPolygon(painter: Painter, m: RasterModel): void {
  painter.polyline(m.state.p, {
    color: painter.theme.polygon,
    width: painter.theme.sizes.thin,
    dash: [6, 5],
  });
}

function drawPlot(painter: Painter, m: RasterModel, labels: boolean): void {
  const k = m.state.step;
  const color = painter.color(0);
  controlPolygon(painter, m);
  if (k >= 3) drawCurve(painter, m.curve);
  if (k >= 2) drawPolyline(painter, m.uniform.points, color);
  else if (k >= 1)
    for (const p of m.uniform.points) painter.dot(p, color, painter.theme.sizes.point);
  if (k >= 4) drawGap(painter, m.uniform, m.state.z, labels);
}

function drawCompare(painter: Painter, m: RasterModel, labels: boolean): void {
  const k = m.state.step;
  controlPolygon(painter, m);
  drawCurve(painter, m.curve);
  if (k >= 3 && m.sameErrorBeyond) {
    // Not computed, so not drawn: the count is past the search's end.
    painter.note(`Uniform sampling needs more than ${SAME_ERROR_MAX} segments for the same gap.`);
    if (labels) heading(painter, `Uniform: more than ${SAME_ERROR_MAX} segments`);
    return;
  }
  const shown = k >= 3 && m.sameError ? m.sameError : m.uniform;
  if (k >= 1) {
    drawPolyline(painter, shown.points, painter.color(k >= 3 ? 2 : 0));
    drawGap(painter, shown, m.state.z, labels);
  }
  if (labels) heading(painter, `Uniform: ${k >= 1 ? `${shown.points.length - 1} segments` : '?'}`);
}

function drawSubdivide(painter: Painter, m: RasterModel): void {
  const shown = piecesShown(m, m.state.step);
  const theme = painter.theme;
  drawCurve(painter, m.curve, shown > 0);
  if (shown === 0) controlPolygon(painter, m);
  for (const node of m.tree.slice(0, shown)) {
    if (node.split) continue;
    drawPolyline(painter, [node.points[0], node.points[node.points.length - 1]], painter.color(0));
  }
  const current = shown > 0 && shown < m.tree.length ? m.tree[shown - 1] : null;
  if (current) {
    const color = current.split ? theme.accent : painter.color(2);
    painter.polyline(current.points, { color, width: theme.sizes.line * 1.2 });
    for (const p of current.points) painter.dot(p, color, theme.sizes.point * 0.7);
  }
}

function drawPixels(painter: Painter, m: RasterModel): void {
  const { size, line } = m;
  const theme = painter.theme;
  const k = m.state.step;
  const all = k >= stepCount(m.state);
  pixelGrid(painter, size);
  if (all) fillPixels(painter, m.pixels.values(), size.zoom, theme.ink, 0.75);
  else {
    const lit = line.pixels.slice(0, pixelsShown(m, k)).map(([i, j]) => ({ i, j, value: 1 }));
    fillPixels(painter, lit, size.zoom, theme.accent, 0.8);
    if (k >= 1) {
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
  if (m.state.step >= 2 && m.coverage)
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
  const [x0, y0] = [size.left / size.zoom, size.bottom / size.zoom];
  const [x1, y1] = [(size.left + size.width) / size.zoom, (size.bottom + size.height) / size.zoom];
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
  if (labels) heading(painter, `The screen's 32 × 24 pixels at zoom ×${size.zoom}: the box`);
}

export const curveFigure: FigureSpec<RasterState, RasterModel> = {
  id: 'curve',
  title: 'The curve, the segments drawn for it, and the pixels they light',
  kind: 'geometry',
  weight: 1.25,
  bounds: (m) => unionBounds(boundsOf(m.state.p), RASTER_BOX),
  draw(painter, m, info) {
    const labels = !info.thumbnail;
    if (m.oneSpot)
      painter.note(
        'All control points are on one spot: the curve is that single point, so every segment has length 0 and covers at most one pixel.',
      );
    switch (m.state.x) {
      case 'plot':
        return drawPlot(painter, m, labels);
      case 'compare':
        return drawCompare(painter, m, labels);
      case 'subdivide':
        return drawSubdivide(painter, m);
      case 'pixels':
        return drawPixels(painter, m);
      case 'coverage':
        return drawCoverage(painter, m);
      case 'zoom':
        return drawZoom(painter, m, labels);
    }
  },
  handles: (m) =>
    m.state.p.map((point, i) => ({
      id: `p${i}`,
      label: `P_{${i}}`,
      position: point,
      small: m.state.x !== 'plot',
    })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? [to[0], to[1]] : point)) };
  },
  addPoint(state, at) {
    if (state.p.length >= MAX_POINTS) return null;
    return { ...state, p: insertPoint(state.p, at) };
  },
  removeHandle(state, id) {
    if (state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return { ...state, p: state.p.filter((_, k) => k !== i) };
  },
};
