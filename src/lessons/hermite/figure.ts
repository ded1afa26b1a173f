import type { KitFigure } from '../../kit/lesson';
import type { HermiteModel } from './model';
import { controlPoints, gradientTips } from './points';
import type { HermiteState } from './state';

export const curveFigure: KitFigure<HermiteState, HermiteModel> = {
  id: 'patches',
  title: 'Cubic Hermite patches through the points, with their gradients',
  kind: 'geometry',
  weight: 1.6,
  bounds: (m) => m.bounds,
  draw(painter, m, info) {
    const theme = painter.theme;
    const { state, segments, patch, shown, built } = m;
    // The order the patches take, faintly: P0 to P1 to … (the points alone say little).
    if (!state.bezier)
      painter.polyline(state.points, {
        color: theme.curveFaint,
        width: theme.sizes.thin,
        dash: [4, 6],
      });
    if (shown.has('bezier')) {
      segments.forEach((segment, i) => {
        const strong = i === patch.index;
        painter.polyline(segment, {
          color: painter.color(3),
          width: strong ? theme.sizes.line : theme.sizes.thin,
          dash: [6, 4],
          alpha: strong ? 1 : 0.6,
        });
        for (const q of segment.slice(1, 3))
          painter.dot(q, painter.color(3), theme.sizes.point * (strong ? 1 : 0.7));
      });
    }
    painter.cubicSegments(segments.slice(0, built), { color: theme.curve, role: 'curve' });
    if (segments.length > 1 && patch.index < built) {
      painter.cubicSegments([segments[patch.index]], {
        color: painter.color(0),
        width: theme.sizes.curve * 1.2,
        role: 'curve',
      });
    }
    if (shown.has('gradients')) {
      state.points.forEach((p, i) =>
        painter.arrow(p, m.tips[i], { color: painter.color(2), width: theme.sizes.line * 1.2 }),
      );
    }
    // The conditions are on the ends of one patch: ring them, μ = 0 and μ = 1.
    const ends = shown.is('conditions') || shown.is('matrix') || shown.is('ends');
    if (ends)
      for (const q of [patch.p0, patch.p1])
        painter.ring(q, theme.sizes.handle * 1.4, { color: theme.accent, width: theme.sizes.line });
    // Over the handles: at μ = 0.3 on the second patch of "several points" it
    // lies on D₁'s tip, and the handle drawn over it hid it.
    if (shown.has('pointAtMu')) painter.movingPoint(m.patch.point, 1.5);
    if (info.thumbnail) return;
    if (ends)
      [patch.p0, patch.p1].forEach((q, end) =>
        painter.labelClear(`μ = ${end}`, q, [...m.marks, ...patch.bezier], {
          color: theme.accent,
          halo: true,
        }),
      );
    if (shown.has('pointAtMu'))
      painter.labelClear('P(μ)', patch.point, m.marks, { halo: true, bold: true });
    if (shown.has('bezier')) {
      patch.bezier.slice(1, 3).forEach((q, j) =>
        painter.labelClear(`B_${j + 1}`, q, [...m.marks, ...patch.bezier], {
          color: painter.color(3),
          halo: true,
        }),
      );
    }
    if (m.note) painter.note(m.note);
  },
  trail: (m) => (m.shown.has('pointAtMu') ? m.patch.point : null),
  // The tips first: each point is drawn over its tip, so where a gradient is
  // zero (Catmull-Rom's ends) the point, not the tip, is what one grabs.
  points: [gradientTips, controlPoints],
  interleave: true,
  addTo: controlPoints,
};
