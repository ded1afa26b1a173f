import type { KitFigure } from '../../kit/lesson';
import { basisValuesAt } from '../../math';
import { texNumber } from '../../render/formula';
import { niceStep } from '../../render/projection';
import { valueColumn } from '../../kit/cursorValues';
import { plotYName } from '../../kit/plotMarks';
import { seriesDash } from '../../kit/seriesColours';
import { CLIP, type LagrangeModel, basisId } from './model';
import type { LagrangeState } from './state';

/** Label each weight on the plot up to this many points (then only the table). */
const LABEL_UP_TO = 6;

/** L_k's value at the cursor as the plot writes it. */
const valueText = (k: number, w: number) => `L_{${k}}(t) = ${texNumber(w, 2).replace('-', '−')}`;

export const basisFigure: KitFigure<LagrangeState, LagrangeModel> = {
  id: 'basis',
  title: 'The Lagrange basis polynomials L_k(t), with the cursor at t',
  kind: 'plot',
  bounds: (m) => m.plotBounds,
  // The weights at t in rows above the plot, off the peaks of the L_k (the
  // widest: a negative one of the last).
  cursorValues: (m) =>
    m.ts.length <= LABEL_UP_TO
      ? { count: m.ts.length, widest: valueText(m.ts.length - 1, -0.5) }
      : { count: 0, widest: '' },
  // L_k(t) depend on the parameter values t_k alone (by value: chord length
  // moves them with the points, equal spacing does not), and on t and the step.
  drawnFrom: (m) => [m.state.t, m.comparison !== null, m.shown.key, ...m.ts],
  draw(painter, m, info) {
    const theme = painter.theme;
    const { ts, weights, plotBounds: bounds, shown } = m;
    const t = m.state.t;
    // L_k is drawn once its step is reached; beside the spline, all of them with the polynomial.
    const all = m.comparison !== null && shown.has('curve');
    const drawn = (k: number) => all || shown.has('basis', k + 1);
    const count = all ? ts.length : shown.count('basis');
    const yStep = niceStep((bounds.maxY - bounds.minY) / 5);
    painter.plotAxes(bounds, 0.1, yStep, 't', '');
    const top = info.thumbnail ? 0 : plotYName(painter, bounds, 'L_k(t)');
    m.basisPieces.forEach((pieces, k) => {
      if (!drawn(k)) return;
      const strong = info.hover === basisId(k);
      for (const piece of pieces) {
        painter.polylineFlat(piece, {
          color: painter.color(k),
          width: strong ? theme.sizes.curve * 1.6 : theme.sizes.line * 1.3,
          dash: seriesDash(painter, k),
        });
      }
    });
    // L_k(t_k) = 1 and L_k(t_j) = 0: a dot where each is 1.
    ts.forEach((tk, k) => {
      if (drawn(k)) painter.dot([tk, 1], painter.color(k), theme.sizes.point * 0.8);
    });
    // The cursor in ink: no basis polynomial has its colour.
    painter.segment([t, bounds.minY], [t, bounds.maxY], {
      color: theme.ink,
      width: theme.sizes.line,
      dash: [theme.sizes.line * 2, theme.sizes.line * 1.5],
    });
    const inView = weights
      .map((w, k) => ({ w, k }))
      .filter(({ w, k }) => drawn(k) && w >= bounds.minY && w <= bounds.maxY);
    for (const { w, k } of inView) painter.dot([t, w], painter.color(k), theme.sizes.point);
    if (!info.thumbnail && count > 0 && ts.length <= LABEL_UP_TO)
      valueColumn(
        painter,
        t,
        bounds,
        top,
        weights.slice(0, count).map((w, k) => ({
          text: valueText(k, w),
          color: painter.color(k),
        })),
      );
    if (!info.thumbnail && m.basisCut && count > 0) {
      const [x, y] = painter.view.toScreen([1, bounds.minY]);
      painter.screenLabel(`cut at ±${CLIP}`, x, y - theme.sizes.small * 1.2, {
        align: 'right',
        size: theme.sizes.small,
        color: theme.muted,
        halo: true,
      });
    }
  },
  handles: (m) => [
    {
      id: 'cursor',
      label: 't',
      position: [m.state.t, m.plotBounds.minY],
      shape: 'diamond',
      // The axis already says t; a label would cover the weights.
      showLabel: false,
    },
  ],
  moveHandle: (state, _id, to) => ({ ...state, t: Math.min(1, Math.max(0, to[0])) }),
  pickAt: (m, at, tolerance) => (Math.abs(at[0] - m.state.t) <= tolerance ? 'cursor' : null),
  hoverAt(m, at, tolerance) {
    if (at[0] < 0 || at[0] > 1) return null;
    // The L_k at the pointer's t, read off the samples: the nearest within reach.
    let best: string | null = null;
    let distance = tolerance * 2;
    basisValuesAt(m.basis, at[0]).forEach((value, k) => {
      if (Math.abs(value - at[1]) < distance) {
        distance = Math.abs(value - at[1]);
        best = basisId(k);
      }
    });
    return best;
  },
};
