import type { KitFigure } from '../../kit/lesson';
import type { Painter } from '../../render/painter';
import { niceStep } from '../../render/projection';
import type { Family } from './families';
import { comparedIndex, curveNear, highlightedIndex } from './hover';
import { plotYName } from '../../kit/plotMarks';
import { seriesDash } from '../../kit/seriesColours';
import type { BlendingModel } from './model';
import type { BlendingState } from './state';

/** Curve labels on the plot stay readable up to this many functions. */
const LABEL_CURVES_UP_TO = 7;

const clampMu = (x: number) => Math.min(1, Math.max(0, Number(x.toFixed(4))));

export const plotFigure: KitFigure<BlendingState, BlendingModel> = {
  id: 'blending',
  title: 'Blending functions W(N, i, μ) with a cursor at μ',
  kind: 'plot',
  bounds: (m) => m.plotBounds,
  // W(N, i, μ) and their values at μ depend on N and μ, not on where the points
  // are (a compared basis may: it is a new object then, and the plot is drawn).
  drawnFrom: (m) => [
    m.state.mu,
    m.n,
    m.state.comparison,
    m.compared,
    m.plotBounds.minY,
    m.plotBounds.maxY,
    m.handleY,
    m.shown.key,
  ],
  draw(painter, m, info) {
    const theme = painter.theme;
    const { plotBounds: bounds, n, compared, drawn } = m;
    const mu = m.state.mu;
    const highlighted = highlightedIndex(info.hover);
    const comparing = compared !== null && drawn.compared > 0;
    if (!info.thumbnail) {
      const yStep = niceStep((bounds.maxY - bounds.minY) / 5);
      painter.plotAxes(bounds, 0.2, yStep, 'μ', '');
      // Beside another basis, the plot names both (B_i's dashed curves
      // under "W(N, i, μ)" alone read as Bernstein's).
      const name = m.bernstein.name;
      plotYName(painter, bounds, comparing ? `${name} and ${compared.name}` : name);
    }

    drawFamily(painter, m.bernstein, {
      dash: undefined,
      faded: drawn.faded,
      highlighted,
      labels: !info.thumbnail && !comparing && n + 1 <= LABEL_CURVES_UP_TO,
      count: drawn.bernstein,
    });
    if (compared && comparing) {
      drawFamily(painter, compared, {
        dash: [9, 5],
        faded: false,
        highlighted: comparedIndex(info.hover),
        labels: !info.thumbnail && compared.labels.length <= LABEL_CURVES_UP_TO,
        count: drawn.compared,
      });
    }

    // The cursor: a vertical line at μ in ink (no basis function's colour),
    // a dot where it meets each curve shown.
    painter.segment([mu, bounds.minY], [mu, m.handleY], {
      color: theme.ink,
      width: theme.sizes.line,
      dash: [theme.sizes.line * 2, theme.sizes.line * 1.5],
    });
    m.weights.forEach((w, i) => {
      if (i >= drawn.weights) return;
      painter.dot([mu, w], painter.color(i), theme.sizes.point * (highlighted === i ? 1.4 : 1));
    });
    if (compared && drawn.atMu) {
      compared.atMu.forEach((w) => {
        painter.ring([mu, w], theme.sizes.point, { color: theme.ink, width: theme.sizes.thin });
      });
    }
    if (drawn.mirror) drawMirror(painter, m);
  },
  handles: (m) => [{ id: 'mu', label: 'μ', position: [m.state.mu, m.handleY], shape: 'diamond' }],
  // The cursor moves along μ only: the height of the pointer does not matter.
  moveHandle: (state, _id, to) => ({ ...state, mu: clampMu(to[0]) }),
  pickAt(m, at, tolerance) {
    const onLine = Math.abs(at[0] - m.state.mu) <= tolerance;
    return onLine && at[1] >= m.plotBounds.minY && at[1] <= m.plotBounds.maxY ? 'mu' : null;
  },
  hoverAt(m, at) {
    if (at[0] < 0 || at[0] > 1) return null;
    return curveNear(m, at, 0.03 * (m.plotBounds.maxY - m.plotBounds.minY));
  },
  weight: 1,
};

/**
 * The symmetry μ → 1 − μ: the mirrored cursor, and for each pair so far
 * W(N, i, μ) on the first cursor joined level to W(N, N − i, 1 − μ) on the
 * second (both ways round).
 */
function drawMirror(painter: Painter, m: BlendingModel): void {
  const theme = painter.theme;
  const { plotBounds: bounds, n, weights, drawn } = m;
  const mu = m.state.mu;
  painter.segment([1 - mu, bounds.minY], [1 - mu, m.handleY], {
    color: theme.muted,
    width: theme.sizes.line,
    dash: [theme.sizes.line * 2, theme.sizes.line * 1.5],
  });
  for (let pair = 0; pair < drawn.pairs; pair++) {
    for (const i of new Set([pair, n - pair])) {
      const w = weights[i];
      painter.segment([mu, w], [1 - mu, w], { color: painter.color(i), width: theme.sizes.line });
      painter.dot([mu, w], painter.color(i), theme.sizes.point);
      painter.dot([1 - mu, w], painter.color(n - i), theme.sizes.point);
    }
  }
}

interface FamilyStyle {
  dash: number[] | undefined;
  faded: boolean;
  highlighted: number | null;
  labels: boolean;
  /** Functions 0 … count − 1 are drawn (the step reveals them one by one). */
  count: number;
}

function drawFamily(painter: Painter, family: Family, style: FamilyStyle): void {
  const theme = painter.theme;
  family.samples.curves.forEach((curve, i) => {
    if (i >= style.count) return;
    const color = painter.color(family.colors[i]);
    const lit = style.highlighted === i;
    const dim = style.faded || (style.highlighted !== null && !lit);
    painter.polylineFlat(curve, {
      color,
      width: lit ? theme.sizes.curve * 1.6 : theme.sizes.curve * (style.faded ? 0.6 : 0.8),
      dash: style.dash ?? seriesDash(painter, family.colors[i]),
      alpha: dim ? 0.35 : 1,
    });
    if (!style.labels) return;
    // Each function is labelled where it is largest; at the ends, inside the
    // plot and clear of the axis numbers.
    const peak = family.peaks[i];
    const at = [curve[2 * peak], curve[2 * peak + 1]];
    const edge = at[0] < 0.08 ? 'left' : at[0] > 0.92 ? 'right' : 'center';
    painter.label(family.labels[i], at, {
      dx:
        edge === 'left' ? theme.sizes.small * 0.6 : edge === 'right' ? -theme.sizes.small * 0.6 : 0,
      dy: (at[1] < 0 ? 1 : -1) * theme.sizes.small,
      align: edge,
      color,
      size: theme.sizes.small,
      halo: true,
      bold: lit,
    });
  });
}
