import type { FigureSpec, Handle, Point } from '../../app/lesson';
import { ARROW_SCALE, type HermiteModel } from './model';
import { keepLastStep } from '../../kit/keepLastStep';
import { type HermiteState, MAX_POINTS, patchCount, stepCount } from './state';

export const curveFigure: FigureSpec<HermiteState, HermiteModel> = {
  id: 'patches',
  title: 'Cubic Hermite patches through the points, with their gradients',
  kind: 'geometry',
  weight: 1.6,
  bounds: (m) => m.bounds,
  draw(painter, m, info) {
    const theme = painter.theme;
    const { state, segments, patch, shown } = m;
    // The order the patches take, faintly: P0 to P1 to … (the points alone say little).
    painter.polyline(state.p, { color: theme.curveFaint, width: theme.sizes.thin, dash: [4, 6] });
    if (shown.bezier) {
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
    const built = segments.slice(0, shown.patches);
    painter.cubicSegments(built, { color: theme.curve, role: 'curve' });
    if (segments.length > 1 && patch.index < shown.patches) {
      painter.cubicSegments([segments[patch.index]], {
        color: painter.color(0),
        width: theme.sizes.curve * 1.2,
        role: 'curve',
      });
    }
    if (shown.gradients) {
      state.p.forEach((p, i) =>
        painter.arrow(p, m.tips[i], { color: painter.color(2), width: theme.sizes.line * 1.2 }),
      );
    }
    if (shown.point) painter.dot(patch.point, theme.accent, theme.sizes.point * 1.5);
    if (info.thumbnail) return;
    if (shown.point) painter.labelClear('P(μ)', patch.point, m.marks, { halo: true, bold: true });
    if (shown.bezier) {
      patch.bezier.slice(1, 3).forEach((q, j) =>
        painter.labelClear(`B_${j + 1}`, q, [...m.marks, ...patch.bezier], {
          color: painter.color(3),
          halo: true,
        }),
      );
    }
    if (m.note) painter.note(m.note);
  },
  trail: (m) => (m.shown.point ? m.patch.point : null),
  handles(m) {
    const points: Handle[] = m.state.p.map((position, i) => ({
      id: `p${i}`,
      label: `P_{${i}}`,
      position,
    }));
    if (!m.shown.gradients) return points;
    const tips: Handle[] = m.tips.map((position, i) => ({
      id: `d${i}`,
      label: `D_{${i}}`,
      position,
      shape: 'square',
    }));
    // Each point after its own tip: drawn on top, so with a zero gradient
    // (Catmull-Rom's ends) the point, not the tip, is what one grabs.
    return points.flatMap((point, i) => [tips[i], point]);
  },
  moveHandle(state, id, to, m) {
    const i = Number(id.slice(1));
    const at: Point = [to[0], to[1]];
    if (id.startsWith('p')) {
      return { ...state, p: state.p.map((point, k) => (k === i ? at : point)) };
    }
    // Dragging a tip sets D = 3 (tip − P); an automatic gradient becomes a hand-set one.
    const p = state.p[i];
    const d = m.gradients.map((v, k): Point =>
      k === i ? [(at[0] - p[0]) / ARROW_SCALE, (at[1] - p[1]) / ARROW_SCALE] : v,
    );
    return { ...state, mode: 'hand', d };
  },
  addPoint(state, to) {
    if (state.p.length >= MAX_POINTS) return null;
    const at: Point = [to[0], to[1]];
    const last = state.p[state.p.length - 1];
    // A new point arrives heading away from the last one.
    const d: Point = [at[0] - last[0], at[1] - last[1]];
    return keepLastStep(state, { ...state, p: [...state.p, at], d: [...state.d, d] }, stepCount);
  },
  removeHandle(state, id) {
    if (!id.startsWith('p') || state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    const after = {
      ...state,
      p: state.p.filter((_, k) => k !== i),
      d: state.d.filter((_, k) => k !== i),
      patch: Math.min(state.patch, patchCount(state) - 2),
    };
    return keepLastStep(state, after, stepCount);
  },
};
