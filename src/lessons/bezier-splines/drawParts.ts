import type { DrawInfo } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import { catmull } from './drawCatmull';
import { inspector } from './drawInspector';
import { degree, worked } from './drawWorked';
import type { BezierSplinesModel } from './model';
import { dashed, labelAt, polygons } from './strokes';

// What the main figure shows of each part: each asks what its steps have revealed.

export type Draw = (painter: Painter, m: BezierSplinesModel, info: DrawInfo) => void;

const why: Draw = (painter, m) => {
  const { shown } = m;
  const theme = painter.theme;
  if (!shown.has('single')) return;
  painter.polyline(m.state.points, dashed(painter));
  const single = !shown.has('pieces');
  painter.polylineFlat(m.single, single ? { role: 'curve' } : { color: theme.curveFaint });
  if (shown.is('moved')) {
    painter.polylineFlat(m.singleMoved, { color: theme.accent, dash: [10, 6] });
    painter.arrow(m.state.points[m.moved], m.movedPoints[m.moved], { color: theme.accent });
  }
  if (shown.has('pieces')) painter.cubicSegments(m.spline, { role: 'curve' });
  if (shown.has('local')) {
    painter.cubicSegments(m.movedSpline, {
      color: theme.accent,
      width: theme.sizes.line,
      dash: [10, 6],
    });
    painter.arrow(m.state.points[m.moved], m.movedPoints[m.moved], { color: theme.accent });
  }
};

const quadratic: Draw = (painter, m, info) => {
  const { shown } = m;
  const p = m.state.points;
  const theme = painter.theme;
  if (!shown.has('firstPiece')) return;
  // The first piece, then one more with each mirror image bᵢ.
  const pieces = 1 + shown.count('mirror');
  if (shown.has('swing')) {
    for (const ghost of m.swing)
      painter.cubicSegments(ghost, { color: theme.accent, width: theme.sizes.line, dash: [8, 6] });
  }
  painter.cubicSegments(m.quadratic.slice(0, pieces), { role: 'curve' });
  for (let i = 0; i < pieces; i++) {
    const b = m.quadraticControls[i];
    painter.polyline([p[i], b, p[i + 1]], dashed(painter));
    if (i > 0) {
      painter.dot(b, theme.accent, theme.sizes.point * 1.3);
      if (!info.thumbnail) labelAt(painter, `b_{${i}}`, b, theme.accent);
    }
  }
};

const system: Draw = (painter, m, info) => {
  const { shown } = m;
  const p = m.state.points;
  const theme = painter.theme;
  if (!shown.has('unknowns')) return;
  const solved = shown.has('solution');
  if (!solved) painter.polyline(p, { ...dashed(painter), color: theme.curveFaint });
  const n = p.length - 1;
  // Where the step's equations hold: the inner joints (C¹, C²) or the two ends.
  const marked =
    shown.is('c1Equations') || shown.is('c2Equations')
      ? p.slice(1, -1)
      : shown.is('naturalEnds')
        ? [p[0], p[n]]
        : [];
  for (const q of marked) painter.ring(q, theme.sizes.handle * 2.2, { color: theme.accent });
  if (!solved) return;
  const natural = shown.has('sameAsNatural');
  if (natural)
    painter.cubicSegments(m.natural, { color: theme.curveFaint, width: theme.sizes.curve * 2.4 });
  const controls = m.system.controls;
  const pieces = Array.from({ length: n }, (_, i) => controls.slice(3 * i, 3 * i + 4));
  polygons(painter, pieces);
  painter.cubicSegments(pieces, { role: 'curve' });
  if (!info.thumbnail)
    controls.forEach((q, j) => {
      if (j % 3 !== 0) labelAt(painter, m.names[j], q, theme.accent);
    });
  if (natural)
    painter.cubicSegments(m.natural, {
      color: theme.accent,
      width: theme.sizes.line,
      dash: [4, 8],
    });
};

export const drawParts: Record<BezierSplinesModel['state']['part'], Draw> = {
  why,
  quadratic,
  system,
  grid: () => undefined,
  inspector,
  catmull,
  worked,
  degree,
};
