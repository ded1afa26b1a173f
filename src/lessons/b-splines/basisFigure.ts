import type { DrawInfo, FigureSpec } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import type { BSplineModel } from './model';
import { basisBounds, tFor, uStep } from './plotRange';
import { type BSplineState, isUniformPart } from './state';

/** Which row of the Cox–de Boor triangle the plot shows now, or null for none yet. */
export function shownRow(s: BSplineState, degree: number): number | null {
  const k = s.k;
  switch (s.x) {
    case 'uniform':
    case 'closed':
      return k >= 3 ? degree : null;
    case 'local':
      return k >= 3 ? degree : null;
    case 'knots':
    case 'clamped':
    case 'repeated':
      return k >= 2 ? Math.min(k - 2, degree) : null;
    case 'circle':
    case 'projective':
      return k >= 2 ? degree : null;
    default:
      return k >= 1 ? degree : null;
  }
}

/** Grey where the curve is not defined: outside [u_p, u_{n}]. */
function shadeOutside(painter: Painter, m: BSplineModel, bounds = basisBounds(m)): void {
  const [a, b] = m.domain;
  const { minX, maxX, minY, maxY } = bounds;
  const fill = painter.theme.muted;
  if (a > minX)
    painter.polygon(
      [
        [minX, minY],
        [a, minY],
        [a, maxY],
        [minX, maxY],
      ],
      fill,
      0.1,
    );
  if (b < maxX)
    painter.polygon(
      [
        [b, minY],
        [maxX, minY],
        [maxX, maxY],
        [b, maxY],
      ],
      fill,
      0.1,
    );
}

function drawBasis(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const bounds = basisBounds(m);
  const r = shownRow(m.state, m.degree);
  painter.plotAxes(bounds, uStep(m), 0.25, isUniformPart(m.state.x) ? 's' : 'u', '');
  shadeOutside(painter, m, bounds);
  const seg = /^seg(\d+)$/.exec(info.hover ?? '');
  if (seg && m.segments[Number(seg[1])]) {
    const { from, to } = m.segments[Number(seg[1])];
    painter.polygon(
      [
        [from, 0],
        [to, 0],
        [to, 1],
        [from, 1],
      ],
      painter.color(Number(seg[1])),
      0.15,
    );
  }
  if (r === null) {
    if (!info.thumbnail) painter.note('The basis functions appear as the steps go on');
    return;
  }
  const hovered = /^p(\d+)$/.exec(info.hover ?? '');
  const owner = (i: number) => (r === m.degree ? (m.owner[i] ?? i) : i);
  m.rows[r].forEach((samples, i) => {
    const strong = hovered !== null && Number(hovered[1]) === owner(i);
    painter.polylineFlat(samples, {
      color: painter.color(owner(i)),
      width: strong ? theme.sizes.curve * 1.5 : theme.sizes.line * 1.3,
    });
  });
  const u = m.u;
  painter.segment([u, bounds.minY], [u, bounds.maxY], {
    color: theme.accent,
    width: theme.sizes.line,
  });
  const values = m.table[r];
  const entries = values.flatMap((v, i) =>
    v > 0
      ? [{ y: v, text: `N_{${i},${r}} = ${v.toFixed(3)}`, color: painter.color(owner(i)) }]
      : [],
  );
  for (const e of entries) painter.dot([u, e.y], e.color, theme.sizes.point);
  if (!info.thumbnail) painter.cursorLabels(u, entries);
}

export const basisFigure: FigureSpec<BSplineState, BSplineModel> = {
  id: 'basis',
  title: 'The B-spline basis functions, with the cursor at the parameter',
  kind: 'plot',
  weight: 1,
  bounds: basisBounds,
  draw: drawBasis,
  handles: (m) => [
    {
      id: 'cursor',
      label: 'u',
      position: [m.u, basisBounds(m).minY],
      shape: 'diamond',
      showLabel: false,
    },
  ],
  moveHandle: (state, _id, to, m) => ({ ...state, t: tFor(m, to[0]) }),
  pickAt: (m, at, tolerance) => (Math.abs(at[0] - m.u) <= tolerance ? 'cursor' : null),
  hoverAt(m, at, tolerance) {
    const r = shownRow(m.state, m.degree);
    if (r !== m.degree) return null;
    let best: string | null = null;
    let distance = tolerance * 2;
    m.rows[r].forEach((samples, i) => {
      for (let k = 0; k + 1 < samples.length; k += 2) {
        if (Math.abs(samples[k] - at[0]) > tolerance) continue;
        const d = Math.abs(samples[k + 1] - at[1]);
        if (d < distance && samples[k + 1] > 1e-6) {
          distance = d;
          best = `p${m.owner[i] ?? i}`;
        }
      }
    });
    return best;
  },
};
