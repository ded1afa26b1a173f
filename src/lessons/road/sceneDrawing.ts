import type { DrawInfo } from '../../app/lesson';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import { drawFigureNote, drawRoadway } from './mapDrawing';
import type { RoadModel } from './model';
import { LABEL_VILLAGES } from './points';
import { asCubics } from './roads';

// What the map draws in the derivation and the global view, around the
// natural road. Every position comes from the model.

/** The segments and villages a step of the derivation talks about. */
export function derivationFocus(m: RoadModel): { pieces: number[]; villages: number[] } {
  const work = m.derivation;
  const none = { pieces: [], villages: [] };
  if (!work) return none;
  const j = work.join ?? 1;
  const last = work.m;
  switch (m.shown.name) {
    case 'parameter':
      return { pieces: [m.along.piece], villages: [] };
    case 'left':
    case 'second':
      return { pieces: [j - 1], villages: [j] };
    case 'right':
      return { pieces: [j], villages: [j] };
    case 'equal':
    case 'substitute':
      return { pieces: [j - 1, j], villages: [j] };
    case 'row':
      return { pieces: [j - 1, j], villages: [j - 1, j, j + 1] };
    case 'start':
      return { pieces: [0], villages: [0] };
    case 'end':
      return { pieces: [last - 1], villages: [last] };
    default:
      return none;
  }
}

/** The derivation's step on the map: the segments it talks about in the accent colour, its join ringed. */
export function drawDerivationFocus(painter: Painter, m: RoadModel): void {
  const pieces = m.visible?.cubics ?? [];
  const { theme } = painter;
  const focus = derivationFocus(m);
  const chosen = focus.pieces.filter((i) => i >= 0 && i < pieces.length).map((i) => pieces[i]);
  if (chosen.length)
    painter.cubicSegments(chosen, { color: theme.accent, width: theme.sizes.curve * 1.7 });
  for (const i of focus.villages) {
    const village = m.state.villages[i];
    if (village)
      painter.ring(village, theme.sizes.handle * 2.4, {
        color: theme.accent,
        width: theme.sizes.line * 1.5,
      });
  }
}

/** Arrows D/3 from each village (up to LABEL_VILLAGES of them). */
function drawGradients(
  painter: Painter,
  villages: readonly Point[],
  gradients: readonly Point[],
  color: string,
  width: number,
): void {
  if (villages.length > LABEL_VILLAGES) return;
  villages.forEach((p, i) => {
    const d = gradients[i];
    painter.arrow(p, [p[0] + d[0] / 3, p[1] + d[1] / 3], { color, width });
  });
}

/**
 * The global view: the road and its gradients; then one village moved, the
 * road before it faint and the new one with its gradients; then the villages
 * mapped by an affine map, the mapped road dashed over the road through them.
 */
export function drawGlobal(painter: Painter, m: RoadModel, info: DrawInfo): void {
  const change = m.globalChange;
  if (!change) return;
  const { theme } = painter;
  const { shown } = m;
  const road = asCubics(change.road.pieces);
  const line = theme.sizes.line;
  const mapping = shown.has('map');
  const moving = shown.has('move') && !mapping;
  if (moving) {
    const { moved } = change;
    drawRoadway(painter, road, theme.curveFaint);
    drawRoadway(painter, asCubics(moved.road.pieces), painter.color(4), true);
    const from = change.road.villages[moved.index];
    const to = moved.road.villages[moved.index];
    painter.ring(from, theme.sizes.handle * 1.6, {
      color: theme.muted,
      width: theme.sizes.thin,
      dash: [3, 3],
    });
    painter.arrow(from, to, { color: theme.accent, width: line * 1.4 });
    painter.dot(to, theme.accent, theme.sizes.point);
    if (shown.has('changes') && !info.thumbnail) {
      drawGradients(painter, change.road.villages, change.road.gradients, theme.curveFaint, line);
      drawGradients(painter, moved.road.villages, moved.road.gradients, theme.accent, line * 1.2);
    }
    return;
  }
  drawRoadway(painter, road, painter.color(4), true);
  if (!mapping) {
    if (!info.thumbnail)
      drawGradients(painter, change.road.villages, change.road.gradients, painter.color(0), line);
    return;
  }
  const { mapped } = change;
  if (shown.has('mapped'))
    drawRoadway(painter, asCubics(mapped.road.pieces), painter.color(2), true);
  // The old road mapped: accent dashes, laid over the road through the mapped villages.
  painter.cubicSegments(asCubics(mapped.mappedRoad), {
    color: theme.accent,
    width: line * 1.6,
    dash: [line * 4, line * 3],
  });
  for (const p of mapped.road.villages) painter.dot(p, painter.color(2), theme.sizes.point);
  if (!info.thumbnail && m.mapNotes.length) drawFigureNote(painter, m.mapNotes);
}
