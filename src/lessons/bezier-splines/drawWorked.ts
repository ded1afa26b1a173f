import type { DrawInfo } from '../../app/lesson';
import { bezierPoint, type Point } from '../../math';
import type { Painter } from '../../render/painter';
import type { BezierSplinesModel } from './model';
import { piecesOf } from './pieces';
import { itemsShown, pressItems } from './presses';
import { dashed, labelAt, polygons } from './strokes';

type Draw = (painter: Painter, m: BezierSplinesModel, info: DrawInfo) => void;

/** Part 7: the C¹ pieces one bᵢ at a time, then the C² walk: where each equation holds, B, the rest. */
export const worked: Draw = (painter, m, info) => {
  const { shown } = m;
  const p = m.state.points;
  const n = p.length - 1;
  const theme = painter.theme;
  const labels = !info.thumbnail;
  if (!shown.has('c1Count')) return;
  const { c1, c2 } = m.worked;
  const quadratic = m.degree.row.c1;
  const cubic = shown.has('c2Count');
  // The C² spline's pieces, as computeSplineC2 returns them.
  const solved = cubic ? piecesOf(c2.controls) : [];
  if (cubic) {
    // The C¹ spline stays behind, faint, for comparison, and named: unnamed,
    // a grey curve beside "they agree to 12 digits" read as the C² spline's.
    painter.cubicSegments(quadratic, { color: theme.curveFaint, width: theme.sizes.line });
    if (labels) nameFaint(painter, quadratic, solved, 'C¹ spline');
  } else {
    painter.polyline(p, { ...dashed(painter), color: theme.curveFaint });
    const count = shown.has('c1First') ? 1 + itemsShown(n - 1, shown.count('c1Mirror')) : 0;
    painter.cubicSegments(quadratic.slice(0, count), { role: 'curve' });
    for (let i = 0; i < count; i++) {
      painter.polyline([p[i], c1.b[i], p[i + 1]], dashed(painter));
      painter.dot(c1.b[i], theme.accent, theme.sizes.point * 1.3);
      if (labels) labelAt(painter, `b_{${i}}`, c1.b[i], theme.accent);
    }
    // The output's row numbers, as the checker numbers them.
    if (shown.has('c1Output') && labels)
      c1.output.forEach((q, j) =>
        painter.label(String(j), q, { dx: -12, dy: 16, color: theme.muted, halo: true }),
      );
    return;
  }
  // Where the step's equations hold: the start, the joints of this press, the end.
  const ringed = shown.is('c2Start')
    ? [p[0]]
    : shown.is('c2Joint')
      ? pressItems(n - 1, shown.index).map((i) => p[i])
      : shown.is('c2End')
        ? [p[n]]
        : [];
  for (const q of ringed) painter.ring(q, theme.sizes.handle * 2.2, { color: theme.accent });
  if (!shown.has('c2End')) return;
  if (shown.has('c2Back')) polygons(painter, solved);
  painter.dot(c2.B, theme.accent, theme.sizes.point * 1.3);
  if (labels)
    c2.controls.forEach((q, j) => {
      if (j === 1 || (j % 3 !== 0 && shown.has('c2Back')))
        labelAt(painter, m.names[j], q, theme.accent);
    });
  if (shown.has('c2Output')) painter.cubicSegments(solved, { role: 'curve' });
};

/** Part 8: degree 1, 2, 3 in turn (the earlier ones faint), all three, then the first cubic continued. */
export const degree: Draw = (painter, m, info) => {
  const { shown } = m;
  const theme = painter.theme;
  const { row, continued } = m.degree;
  const all = shown.is('general');
  const layers = [
    ['degree1', row.c0],
    ['degree2', row.c1],
    ['degree3', row.c2],
  ] as const;
  layers.forEach(([name, segments], column) => {
    if (!shown.has(name)) return;
    const current = all || shown.is(name) || (name === 'degree3' && shown.has('notCd'));
    if (!current) {
      painter.cubicSegments(segments, { color: theme.curveFaint, width: theme.sizes.line });
      return;
    }
    painter.cubicSegments(segments, { role: 'curve', color: painter.color(column) });
    // Each degree named beside its middle piece once all three are drawn.
    if (all && !info.thumbnail) {
      const middle = segments[Math.floor((segments.length - 1) / 2)];
      labelAt(painter, `d = ${column + 1}`, bezierPoint(middle, 0.5), painter.color(column));
    }
  });
  if (!shown.has('notCd')) return;
  painter.cubicSegments([continued], {
    color: theme.accent,
    width: theme.sizes.line,
    dash: [8, 6],
  });
  const p = m.state.points;
  if (p.length > 2) painter.ring(p[2], theme.sizes.handle * 2.2, { color: theme.accent });
  // Its end, P₀(2), is the point the step is about: it is not p₂ (the dashed
  // piece passes near p₂ on its way, at another t).
  painter.dot(continued[3], theme.accent, theme.sizes.point * 1.3);
  if (!info.thumbnail) {
    labelAt(painter, 'P_0(1 + t)', bezierPoint(continued, 0.8), theme.accent);
    labelAt(painter, 'P_0(2)', continued[3], theme.accent);
  }
};

/**
 * Names a faint curve kept for comparison at the middle of its piece that
 * stands farthest from the same piece of `other`, where it is seen apart.
 */
function nameFaint(
  painter: Painter,
  faint: readonly (readonly Point[])[],
  other: readonly (readonly Point[])[],
  text: string,
): void {
  let at: Point | null = null;
  let apart = -1;
  faint.forEach((piece, i) => {
    const a = bezierPoint(piece, 0.5);
    const b = other[i] ? bezierPoint(other[i], 0.5) : a;
    const d = Math.hypot(a[0] - b[0], a[1] - b[1]);
    if (d > apart) [at, apart] = [a, d];
  });
  if (at) labelAt(painter, text, at, painter.theme.muted);
}
