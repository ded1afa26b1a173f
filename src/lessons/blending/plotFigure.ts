import type { FigureSpec } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import { type Bounds, niceStep } from '../../render/viewport';
import { type Basis, bernsteinFamily, comparisonFamily, sampleBasis } from './bases';
import { highlightedIndex } from './curveFigure';
import { type BlendingState, degree } from './state';

const SAMPLES = 240;

/** Curve labels on the plot stay readable up to this many functions. */
const LABEL_CURVES_UP_TO = 7;

/** The plot's axes: μ from 0 to 1; W from its lowest to its highest value, with room for the cursor's handle. */
function plotBounds(state: BlendingState): Bounds {
  let low = 0;
  let high = 1;
  const other = comparisonFamily(state.b, degree(state));
  if (other) {
    for (const row of sampleBasis(other, SAMPLES).values) {
      for (const v of row) {
        low = Math.min(low, v);
        high = Math.max(high, v);
      }
    }
  }
  const span = high - low;
  return { minX: 0, maxX: 1, minY: low - 0.04 * span, maxY: high + 0.16 * span };
}

/** Where the cursor's handle sits: at the top of the plot, clear of the curves. */
const handleHeight = (bounds: Bounds) => bounds.maxY - 0.05 * (bounds.maxY - bounds.minY);

const clampMu = (x: number) => Math.min(1, Math.max(0, Number(x.toFixed(4))));

export const plotFigure: FigureSpec<BlendingState> = {
  id: 'blending',
  title: 'Blending functions W(N, i, μ) with a cursor at μ',
  kind: 'plot',
  bounds: plotBounds,
  draw(painter, state, info) {
    const theme = painter.theme;
    const bounds = plotBounds(state);
    const n = degree(state);
    const highlighted = highlightedIndex(info.hover);
    const comparisonHover =
      info.hover && /^c\d+$/.test(info.hover) ? Number(info.hover.slice(1)) : null;
    if (!info.thumbnail) {
      const yStep = niceStep((bounds.maxY - bounds.minY) / 5);
      painter.plotAxes(bounds, 0.2, yStep, 'μ', 'W');
    }

    const other = comparisonFamily(state.b, n);
    const bernstein = bernsteinFamily(n);
    drawFamily(painter, bernstein, {
      dash: undefined,
      faded: other !== null,
      highlighted,
      labels: !info.thumbnail && !other && n + 1 <= LABEL_CURVES_UP_TO,
      colorOf: (i) => painter.color(i),
    });
    if (other) {
      drawFamily(painter, other, {
        dash: [9, 5],
        faded: false,
        highlighted: comparisonHover,
        labels: !info.thumbnail && other.labels.length <= LABEL_CURVES_UP_TO,
        colorOf: (i) => painter.color(state.b === 'hermite' ? hermiteColorIndex(i, n) : i),
      });
    }

    // The cursor: a vertical line at μ, a dot where it meets each curve.
    const top = handleHeight(bounds);
    painter.segment([state.mu, bounds.minY], [state.mu, top], {
      color: theme.accent,
      width: theme.sizes.line,
    });
    bernstein.values(state.mu).forEach((w, i) => {
      painter.dot(
        [state.mu, w],
        painter.color(i),
        theme.sizes.point * (highlighted === i ? 1.4 : 1),
      );
    });
    if (other) {
      other.values(state.mu).forEach((w) => {
        painter.ring([state.mu, w], theme.sizes.point, {
          color: theme.ink,
          width: theme.sizes.thin,
        });
      });
    }
  },
  handles: (state) => [
    {
      id: 'mu',
      label: 'μ',
      position: [state.mu, handleHeight(plotBounds(state))],
      shape: 'diamond',
    },
  ],
  // The cursor moves along μ only: the height of the pointer does not matter.
  moveHandle: (state, _id, to) => ({ ...state, mu: clampMu(to[0]) }),
  pickAt(state, at, tolerance) {
    const bounds = plotBounds(state);
    const onLine = Math.abs(at[0] - state.mu) <= tolerance;
    return onLine && at[1] >= bounds.minY && at[1] <= bounds.maxY ? 'mu' : null;
  },
  hoverAt(state, at) {
    if (at[0] < 0 || at[0] > 1) return null;
    const bounds = plotBounds(state);
    const reach = 0.03 * (bounds.maxY - bounds.minY);
    const nearest = (values: number[]) => {
      let best = -1;
      let bestDistance = reach;
      values.forEach((v, i) => {
        if (Math.abs(v - at[1]) <= bestDistance) {
          best = i;
          bestDistance = Math.abs(v - at[1]);
        }
      });
      return best;
    };
    const other = comparisonFamily(state.b, degree(state));
    if (other) {
      const i = nearest(other.values(at[0]));
      if (i >= 0) return `c${i}`;
    }
    const i = nearest(bernsteinFamily(degree(state)).values(at[0]));
    return i >= 0 ? `w${i}` : null;
  },
  weight: 1,
};

/** H0 weights x0 = P0, H1 weights x1 = PN: they share those points' colours; H2, H3 follow. */
export const hermiteColorIndex = (i: number, n: number) => [0, n, 1, Math.max(2, n - 1)][i];

interface FamilyStyle {
  dash: number[] | undefined;
  faded: boolean;
  highlighted: number | null;
  labels: boolean;
  colorOf(i: number): string;
}

function drawFamily(painter: Painter, basis: Basis, style: FamilyStyle): void {
  const theme = painter.theme;
  const { mu, values } = sampleBasis(basis, SAMPLES);
  values.forEach((row, i) => {
    const lit = style.highlighted === i;
    const dim = style.faded || (style.highlighted !== null && !lit);
    const flat = new Float64Array(2 * mu.length);
    mu.forEach((m, k) => {
      flat[2 * k] = m;
      flat[2 * k + 1] = row[k];
    });
    painter.polylineFlat(flat, {
      color: style.colorOf(i),
      width: lit ? theme.sizes.curve * 1.6 : theme.sizes.curve * (style.faded ? 0.6 : 0.8),
      dash: style.dash,
      alpha: dim ? 0.35 : 1,
    });
    if (style.labels) {
      // Label each function where it is largest: W(N, i, μ) peaks at μ = i/N.
      let peak = 0;
      row.forEach((v, k) => {
        if (Math.abs(v) > Math.abs(row[peak])) peak = k;
      });
      // At the ends, keep the label inside the plot, clear of the axis numbers.
      const edge = mu[peak] < 0.08 ? 'left' : mu[peak] > 0.92 ? 'right' : 'center';
      painter.label(basis.labels[i], [mu[peak], row[peak]], {
        dx:
          edge === 'left'
            ? theme.sizes.small * 0.6
            : edge === 'right'
              ? -theme.sizes.small * 0.6
              : 0,
        dy: (row[peak] < 0 ? 1 : -1) * theme.sizes.small,
        align: edge,
        color: style.colorOf(i),
        size: theme.sizes.small,
        halo: true,
        bold: lit,
      });
    }
  });
}
