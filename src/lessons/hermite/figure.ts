import type { FigureSpec, Handle, Point2 } from '../../app/lesson';
import { boundsOf } from '../../render/viewport';
import { patchAt, patchSegments } from './model';
import { type HermiteState, MAX_POINTS, gradients, patchCount } from './state';

/** The arrow for a gradient D is drawn D/3 long: its tip is where the Bézier control point sits. */
export const ARROW_SCALE = 1 / 3;

const tip = (p: Point2, d: Point2): Point2 => [
  p[0] + d[0] * ARROW_SCALE,
  p[1] + d[1] * ARROW_SCALE,
];

export const curveFigure: FigureSpec<HermiteState> = {
  id: 'patches',
  title: 'Cubic Hermite patches through the points, with their gradients',
  kind: 'geometry',
  weight: 1.6,
  bounds(state) {
    const D = gradients(state);
    return boundsOf([
      ...state.p,
      ...state.p.map((p, i) => tip(p, D[i])),
      ...patchSegments(state).flat(),
    ]);
  },
  draw(painter, state, info) {
    const theme = painter.theme;
    const segments = patchSegments(state);
    const patch = patchAt(state);
    if (state.bezier) {
      segments.forEach((segment, i) => {
        const strong = i === state.patch;
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
    painter.cubicSegments(segments, { color: theme.curve });
    if (segments.length > 1) {
      painter.cubicSegments([segments[state.patch]], {
        color: painter.color(0),
        width: theme.sizes.curve * 1.2,
      });
    }
    const D = gradients(state);
    state.p.forEach((p, i) =>
      painter.arrow(p, tip(p, D[i]), { color: painter.color(2), width: theme.sizes.line * 1.2 }),
    );
    painter.dot(patch.point, theme.accent, theme.sizes.point * 1.5);
    if (info.thumbnail) return;
    const crowd = state.p.flatMap((p, i) => [p, tip(p, D[i])]);
    painter.labelClear('P(μ)', patch.point, crowd, { halo: true, bold: true });
    if (state.bezier) {
      patch.bezier.slice(1, 3).forEach((q, j) =>
        painter.label(`B_${j + 1}`, q, {
          dx: 8,
          dy: theme.sizes.label,
          color: painter.color(3),
          halo: true,
        }),
      );
    }
    const [a, b] = [state.p[state.patch], state.p[state.patch + 1]];
    const still = (d: Point2) => d[0] === 0 && d[1] === 0;
    if (a[0] === b[0] && a[1] === b[1] && still(D[state.patch]) && still(D[state.patch + 1])) {
      painter.note(
        `P${state.patch} and P${state.patch + 1} are at one spot and both gradients are zero: four conditions that all say "stay here", so the patch is a single point. Drag a point or a gradient tip away.`,
      );
    } else if (state.mode === 'catmull-rom' && state.p.length === 2) {
      painter.note(
        'Two points have no neighbours: Catmull-Rom gives both ends a zero gradient, so the patch is a straight segment. Add a point.',
      );
    }
  },
  handles(state) {
    const D = gradients(state);
    const points: Handle[] = state.p.map((position, i) => ({
      id: `p${i}`,
      label: `P_${i}`,
      position,
    }));
    const tips: Handle[] = state.p.map((p, i) => ({
      id: `d${i}`,
      label: `D_${i}`,
      position: tip(p, D[i]),
      shape: 'square',
    }));
    // Each point after its own tip: drawn on top, so with a zero gradient
    // (Catmull-Rom's ends) the point, not the tip, is what one grabs.
    return points.flatMap((point, i) => [tips[i], point]);
  },
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    if (id.startsWith('p')) {
      return { ...state, p: state.p.map((point, k) => (k === i ? to : point)) };
    }
    // Dragging a tip sets D = 3 (tip − P); an automatic gradient becomes a hand-set one.
    const D = gradients(state);
    const p = state.p[i];
    const d = D.map((v, k): Point2 =>
      k === i ? [(to[0] - p[0]) / ARROW_SCALE, (to[1] - p[1]) / ARROW_SCALE] : v,
    );
    return { ...state, mode: 'hand', d };
  },
  addPoint(state, at) {
    if (state.p.length >= MAX_POINTS) return null;
    const last = state.p[state.p.length - 1];
    // A new point arrives heading away from the last one.
    const d: Point2 = [at[0] - last[0], at[1] - last[1]];
    return { ...state, p: [...state.p, at], d: [...state.d, d] };
  },
  removeHandle(state, id) {
    if (!id.startsWith('p') || state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return {
      ...state,
      p: state.p.filter((_, k) => k !== i),
      d: state.d.filter((_, k) => k !== i),
      patch: Math.min(state.patch, patchCount(state) - 2),
    };
  },
};
