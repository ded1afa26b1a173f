import type { DrawInfo } from '../../app/lesson';
import type { KitFigure } from '../../kit/lesson';
import { bezierPoint, nearestOnBezierPieces } from '../../math';
import { drawInset } from '../../render/inset';
import type { Painter } from '../../render/painter';
import {
  drawFixedGradients,
  drawMarkerLabel,
  drawMethodAids,
  drawOtherRoads,
  drawSolveProgress,
} from './aids';
import { moveRoadHandle, roadHandles } from './handles';
import {
  drawCurvatureComb,
  drawFigureNote,
  drawLegend,
  drawOverlayCurve,
  drawParameterTicks,
  drawRoadway,
} from './mapDrawing';
import type { RoadModel } from './model';
import { LABEL_VILLAGES, villagePoints } from './points';
import { drawDerivationFocus, drawGlobal } from './sceneDrawing';
import type { ShownRoad } from './shownRoad';
import type { RoadState } from './state';

/** What the pointer is over when it is over shown piece i: `seg3`. */
const segmentId = (piece: number) => `seg${piece}`;

/** The shown piece under the pointer, as an index into the shown pieces, else −1. */
export const hoveredSegment = (m: RoadModel, hover: string | null) =>
  hover === null ? -1 : (m.visible?.pieces ?? []).findIndex((_, i) => segmentId(i) === hover);

export const mapFigure: KitFigure<RoadState, RoadModel> = {
  id: 'map',
  title: 'Map: the villages and the road through them',
  kind: 'geometry',
  bounds: (m) => m.bounds,
  draw(painter, m, info) {
    const { theme } = painter;
    if (m.state.villages.length <= LABEL_VILLAGES && !info.thumbnail) {
      for (const village of m.state.villages)
        painter.ring(village, theme.sizes.handle * 2.2, { alpha: 0 }, painter.color(2), 0.16);
    }
    if (m.shown.is('villages')) drawBare(painter, m, info);
    else if (m.globalChange) drawGlobal(painter, m, info);
    else if (m.visible) {
      drawMethodRoad(painter, m, m.visible, info);
      if (m.derivation) drawDerivationFocus(painter, m);
    } else drawOverlay(painter, m, info);
  },
  trail: (m) => (m.globalChange ? null : (m.visible?.marker?.point ?? null)),
  drawOver(painter, m, info) {
    if (!info.thumbnail && m.visible) drawFixedGradients(painter, m);
  },
  points: [villagePoints],
  addTo: villagePoints,
  handles: roadHandles,
  moveHandle: moveRoadHandle,
  hoverAt(m, at, tolerance) {
    // The global view draws roads of its own: no segment of one is picked out.
    if (!m.visible || m.globalChange) return null;
    const { pieces, boxes } = m.visible;
    const near = nearestOnBezierPieces(pieces, at, { boxes, within: tolerance * 2 });
    return near ? segmentId(near.piece) : null;
  },
};

/** The method's road (or what the solve has built of it so far), its aids and marks. */
function drawMethodRoad(painter: Painter, m: RoadModel, shown: ShownRoad, info: DrawInfo): void {
  const { theme } = painter;
  if (m.usesEndGradients) drawOtherRoads(painter, m);
  if (m.solving) drawSolveProgress(painter, m);
  if (!shown.missing) {
    // The comb first: the road covers the bases of its teeth.
    if (shown.comb) drawCurvatureComb(painter, shown.comb, painter.color(3));
    drawRoadway(painter, shown.cubics, painter.color(4), true);
    const hovered = hoveredSegment(m, info.hover);
    if (hovered >= 0 && hovered < shown.cubics.length && !m.solving) {
      painter.cubicSegments([shown.cubics[hovered]], {
        color: theme.accent,
        width: theme.sizes.curve * 1.2,
      });
    }
  } else if (!info.thumbnail) {
    painter.polyline(m.state.villages, {
      color: theme.curveFaint,
      width: theme.sizes.line,
      dash: [6, 6],
    });
  }
  drawMethodAids(painter, m, info);
  if (info.thumbnail) return;
  if (!shown.missing) drawLoopInset(painter, m, shown);
  if (shown.ticks) drawParameterTicks(painter, shown.ticks);
  drawMarkerLabel(painter, m);
  if (m.mapNotes.length) drawFigureNote(painter, m.mapNotes);
}

/**
 * Two villages on one spot: the segment between them has length zero but a
 * unit of p̄, and the road makes a small loop there, under the two handles
 * (about 60 px on the projector). It is drawn again, magnified, in an inset.
 */
function drawLoopInset(painter: Painter, m: RoadModel, shown: ShownRoad): void {
  const v = m.state.villages;
  const i = v.findIndex((p, k) => k + 1 < v.length && p[0] === v[k + 1][0] && p[1] === v[k + 1][1]);
  const loop = i >= 0 ? shown.cubics[i] : undefined;
  if (!loop) return;
  const samples = Array.from({ length: 33 }, (_, k) => bezierPoint(loop, k / 32));
  const xs = samples.map((q) => q[0]);
  const ys = samples.map((q) => q[1]);
  const region = {
    minX: Math.min(...xs),
    maxX: Math.max(...xs),
    minY: Math.min(...ys),
    maxY: Math.max(...ys),
  };
  drawInset(painter, { region, avoid: v }, (inset) => {
    drawRoadway(inset, shown.cubics, painter.color(4), true);
    for (const p of v) inset.handle(p);
  });
}

/** Step 0: the villages alone, in the order the road will visit them, faintly. */
function drawBare(painter: Painter, m: RoadModel, info: DrawInfo): void {
  const { theme } = painter;
  painter.polyline(m.state.villages, {
    color: theme.curveFaint,
    width: theme.sizes.thin,
    dash: [4, 8],
  });
  if (!info.thumbnail && m.mapNotes.length) drawFigureNote(painter, m.mapNotes);
}

/** Several answers at once, with a legend that says which curve is which. */
function drawOverlay(painter: Painter, m: RoadModel, info: DrawInfo): void {
  for (const curve of m.overlay) drawOverlayCurve(painter, curve);
  drawMethodAids(painter, m, info);
  if (info.thumbnail) return;
  const below = m.overlay.length ? drawLegend(painter, m.overlay) : undefined;
  // Curves left out say why in the legend and the panel; the map keeps the villages' notes.
  if (m.mapNotes.length) drawFigureNote(painter, m.mapNotes, below);
}
