import type { FigureSpec } from '../../app/lesson';
import { lagrangeBasis } from '../../math';
import type { Bounds } from '../../render/viewport';
import { niceStep } from '../../render/viewport';
import { interpolant, sampleBasis } from './model';
import type { LagrangeState } from './state';

/** The plot shows L_k between these values; beyond, the curves are cut and the panel says how far they go. */
const CLIP = 3;
/** Label each weight on the plot up to this many points (then only the table). */
const LABEL_UP_TO = 6;

export const basisFigure: FigureSpec<LagrangeState> = {
  id: 'basis',
  title: 'The Lagrange basis polynomials L_k(t), with the cursor at t',
  kind: 'plot',
  bounds: (state) => plotBounds(sampleBasis(interpolant(state).ts, 200)),
  draw(painter, state, info) {
    const theme = painter.theme;
    const { ts } = interpolant(state);
    const curves = sampleBasis(ts);
    const bounds = plotBounds(curves);
    const yStep = niceStep((bounds.maxY - bounds.minY) / 5);
    painter.plotAxes(bounds, 0.1, yStep, 't', info.thumbnail ? '' : 'L_k(t)');
    const hovered = info.hover ?? '';
    curves.forEach((curve, k) => {
      const strong = hovered === `L${k}`;
      for (const piece of clip(curve, bounds.minY, bounds.maxY)) {
        painter.polylineFlat(piece, {
          color: painter.color(k),
          width: strong ? theme.sizes.curve * 1.6 : theme.sizes.line * 1.3,
        });
      }
    });
    // L_k(t_k) = 1 and L_k(t_j) = 0: a dot where each is 1.
    ts.forEach((tk, k) => painter.dot([tk, 1], painter.color(k), theme.sizes.point * 0.8));
    const weights = lagrangeBasis(ts, state.t);
    painter.segment([state.t, bounds.minY], [state.t, bounds.maxY], {
      color: theme.accent,
      width: theme.sizes.line,
    });
    const shown = weights
      .map((w, k) => ({ w, k }))
      .filter(({ w }) => w >= bounds.minY && w <= bounds.maxY);
    for (const { w, k } of shown) painter.dot([state.t, w], painter.color(k), theme.sizes.point);
    if (!info.thumbnail && ts.length <= LABEL_UP_TO)
      painter.cursorLabels(
        state.t,
        shown.map(({ w, k }) => ({
          y: w,
          text: `L_${k} = ${w.toFixed(2)}`,
          color: painter.color(k),
        })),
      );
    if (!info.thumbnail && clipped(curves)) {
      const [x, y] = painter.view.toScreen([1, bounds.maxY]);
      painter.screenLabel(`cut at ±${CLIP}`, x, y + theme.sizes.small, {
        align: 'right',
        size: theme.sizes.small,
        color: theme.muted,
        halo: true,
      });
    }
  },
  handles: (state) => [
    {
      id: 'cursor',
      label: 't',
      position: [state.t, plotBounds(sampleBasis(interpolant(state).ts, 200)).minY],
      shape: 'diamond',
      // The axis already says t; a label would cover the weights.
      showLabel: false,
    },
  ],
  moveHandle: (state, _id, to) => ({ ...state, t: Math.min(1, Math.max(0, to[0])) }),
  pickAt: (state, at, tolerance) => (Math.abs(at[0] - state.t) <= tolerance ? 'cursor' : null),
  hoverAt(state, at, tolerance) {
    if (at[0] < 0 || at[0] > 1) return null;
    let best: string | null = null;
    let distance = tolerance * 2;
    lagrangeBasis(interpolant(state).ts, at[0]).forEach((w, k) => {
      if (Math.abs(w - at[1]) < distance) {
        distance = Math.abs(w - at[1]);
        best = `L${k}`;
      }
    });
    return best;
  },
};

function plotBounds(curves: readonly Float64Array[]): Bounds {
  let low = -0.3;
  let high = 1.2;
  for (const curve of curves) {
    for (let i = 1; i < curve.length; i += 2) {
      low = Math.min(low, curve[i]);
      high = Math.max(high, curve[i]);
    }
  }
  return { minX: 0, maxX: 1, minY: Math.max(-CLIP, low * 1.05), maxY: Math.min(CLIP, high * 1.05) };
}

const clipped = (curves: readonly Float64Array[]) =>
  curves.some((curve) => curve.some((v, i) => i % 2 === 1 && Math.abs(v) > CLIP));

/** Pieces of a flat [t, y, …] curve inside low ≤ y ≤ high, cut where it crosses out. */
function clip(curve: Float64Array, low: number, high: number): Float64Array[] {
  const pieces: Float64Array[] = [];
  let current: number[] = [];
  const edge = (t0: number, y0: number, t1: number, y1: number) => {
    const bound = y1 > high || y0 > high ? high : low;
    const s = (bound - y0) / (y1 - y0);
    return [t0 + s * (t1 - t0), bound];
  };
  for (let i = 0; i < curve.length; i += 2) {
    const [t, y] = [curve[i], curve[i + 1]];
    const inside = y >= low && y <= high;
    if (i > 0) {
      const [tp, yp] = [curve[i - 2], curve[i - 1]];
      const wasInside = yp >= low && yp <= high;
      if (wasInside && !inside) {
        current.push(...edge(tp, yp, t, y));
        pieces.push(Float64Array.from(current));
        current = [];
      } else if (!wasInside && inside) current.push(...edge(t, y, tp, yp));
    }
    if (inside) current.push(t, y);
  }
  if (current.length >= 4) pieces.push(Float64Array.from(current));
  return pieces;
}
