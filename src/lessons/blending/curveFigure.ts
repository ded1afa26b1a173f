import type { FigureSpec } from '../../app/lesson';
import {
  type Point,
  add,
  bernsteinBasis,
  bezierPoint,
  bezierToHermite,
  lagrangePoint,
  sampleBezier,
  uniformBSplinePoint,
} from '../../math';
import type { Painter } from '../../render/painter';
import { boundsOf, unionBounds } from '../../render/viewport';
import { insertPoint } from '../../interact/editPoints';
import { equallySpacedNodes } from './bases';
import { type BlendingState, MAX_POINTS, degree } from './state';

/** Weight labels beside the points stay readable up to this degree. */
const LABEL_WEIGHTS_UP_TO = 8;

/** The curve a comparison basis gives with the same control points, if it has one. */
function comparisonCurve(state: BlendingState, samples: number): number[][] | null {
  const n = degree(state);
  const ts = Array.from({ length: samples + 1 }, (_, k) => k / samples);
  if (state.b === 'lagrange') {
    const nodes = equallySpacedNodes(n);
    return ts.map((t) => [...lagrangePoint(nodes, state.p, t)]);
  }
  if (state.b === 'bspline' && n >= 3) {
    return ts.map((t) => [...uniformBSplinePoint(state.p, t * (n - 2))]);
  }
  return null;
}

/** The point the comparison weights at μ give, where they weight these control points. */
function comparisonPoint(state: BlendingState): { point: Point; label: string } | null {
  const n = degree(state);
  if (state.b === 'lagrange') {
    return { point: lagrangePoint(equallySpacedNodes(n), state.p, state.mu), label: 'L(μ)' };
  }
  if (state.b === 'bspline' && n === 3) {
    return { point: uniformBSplinePoint(state.p, state.mu), label: 'B(μ)' };
  }
  return null;
}

export const curveFigure: FigureSpec<BlendingState> = {
  id: 'curve',
  title: 'Bézier curve with every control point weighted at μ',
  kind: 'geometry',
  bounds(state) {
    let bounds = boundsOf(state.p);
    const other = comparisonCurve(state, 48);
    if (other) bounds = unionBounds(bounds, boundsOf(other));
    if (state.b === 'hermite' && degree(state) === 3) {
      bounds = unionBounds(bounds, boundsOf(hermiteArrows(state).map(([, tip]) => tip)));
    }
    return bounds;
  },
  draw(painter, state, info) {
    const theme = painter.theme;
    const n = degree(state);
    const weights = bernsteinBasis(n, state.mu);
    const point = bezierPoint(state.p, state.mu);
    const highlighted = highlightedIndex(info.hover);

    const other = comparisonCurve(state, Math.max(96, 24 * n));
    if (other) {
      painter.polyline(other, {
        color: theme.muted,
        width: theme.sizes.curve * 0.8,
        dash: [10, 6],
      });
    }
    if (state.b === 'hermite' && n === 3) drawHermiteData(painter, state);

    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.line, dash: [6, 5] });
    painter.polylineFlat(sampleBezier(state.p, Math.max(64, 24 * n)), { color: theme.curve });

    // Each control point's halo grows with its weight at μ: the curve point is
    // their weighted average, so the biggest halo pulls hardest.
    const largest = theme.sizes.handle * 5;
    state.p.forEach((control, i) => {
      const color = painter.color(i);
      const radius = theme.sizes.handle * 1.3 + largest * weights[i];
      const lit = highlighted === i;
      painter.ring(
        control,
        radius,
        { color, width: lit ? theme.sizes.line * 2 : theme.sizes.thin, alpha: 0.9 },
        color,
        lit ? 0.4 : 0.22,
      );
      painter.segment(control, point, {
        color,
        width: Math.max(theme.sizes.thin, theme.sizes.line * 3 * weights[i]),
        alpha: lit ? 0.9 : 0.45,
      });
      if (!info.thumbnail && n <= LABEL_WEIGHTS_UP_TO) {
        painter.label(weights[i].toFixed(3), control, {
          dy: theme.sizes.handle + theme.sizes.small * 1.1,
          align: 'center',
          color,
          halo: true,
          bold: true,
          size: theme.sizes.small,
        });
      }
    });

    const otherPoint = comparisonPoint(state);
    if (otherPoint) {
      painter.ring(otherPoint.point, theme.sizes.point * 1.4, {
        color: theme.muted,
        width: theme.sizes.line * 1.5,
      });
      if (!info.thumbnail) {
        painter.label(otherPoint.label, otherPoint.point, {
          dx: theme.sizes.point + 6,
          dy: -theme.sizes.label * 0.9,
          color: theme.muted,
          halo: true,
          bold: true,
        });
      }
    }
    painter.dot(point, theme.accent, theme.sizes.point * 1.5);
    if (!info.thumbnail) {
      // Away from the control points and the weights written under them.
      const below = (theme.sizes.handle + theme.sizes.small * 1.1) / painter.view.scaleY;
      const crowd = state.p.flatMap((q) => [q, [q[0], q[1] - below]]);
      painter.labelClear('P(μ)', point, crowd, { color: theme.ink, halo: true, bold: true });
    }
  },
  handles: (state) =>
    state.p.map((point, i) => ({ id: `p${i}`, label: `P_{${i}}`, position: point })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? to : point)) };
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

/** The control point a hover refers to: its handle `p3` or its basis curve `w3`. */
export function highlightedIndex(hover: string | null): number | null {
  const match = hover ? /^[pw](\d+)$/.exec(hover) : null;
  return match ? Number(match[1]) : null;
}

/** The Hermite data of the same cubic: arrows x0 → x0 + x0′ and x1 → x1 + x1′. */
function hermiteArrows(state: BlendingState): [Point, Point][] {
  const [x0, d0, x1, d1] = bezierToHermite(state.p);
  return [
    [x0, add(x0, d0)],
    [x1, add(x1, d1)],
  ];
}

/** The end tangents x0′ = 3(P1 − P0) and x1′ = 3(P3 − P2) at true length: the H2, H3 data. */
function drawHermiteData(painter: Painter, state: BlendingState): void {
  const theme = painter.theme;
  hermiteArrows(state).forEach(([from, tip], k) => {
    painter.arrow(from, tip, { color: theme.accent, width: theme.sizes.line });
    painter.label(k === 0 ? "x_0'" : "x_1'", tip, {
      dx: 6,
      dy: -theme.sizes.label * 0.7,
      color: theme.accent,
      halo: true,
      bold: true,
    });
  });
}
