import type { DrawInfo } from '../../app/lesson';
import type { KitFigure } from '../../kit/lesson';
import { valueColumn } from '../../kit/cursorValues';
import type { Bounds } from '../../render/projection';
import type { Painter } from '../../render/painter';
import { hoveredPoint } from './drawParts';
import { segmentIds } from './ids';
import type { BSplineModel } from './model';
import { basisBounds, tFor, uStep } from './plotRange';
import { type BSplineState, isUniformPart } from './state';

/** Which row of the Cox–de Boor triangle the plot shows now, or null for none yet. */
export function shownRow(m: BSplineModel): number | null {
  const { degree } = m;
  switch (m.kind) {
    case 'uniform':
      return m.shown.has('segments') ? degree : null;
    case 'local':
      return m.shown.has('basis') ? degree : null;
    case 'knots':
      // One row per press, then the last row stays.
      return m.shown.has('row') ? m.shown.count('row') - 1 : null;
    case 'circle':
      return m.shown.has('arcs') ? degree : null;
    case 'projective':
      return m.shown.has('map') ? degree : null;
    case 'convert':
    case 'properties':
      return m.shown.has('curve') ? degree : null;
    case 'nurbs':
      return m.shown.has('plain') ? degree : null;
    case 'meanings':
      return m.shown.has('values') ? degree : null;
    case 'continuity':
      // The step's own degree: the bases' kinks sit at the knots.
      return m.shown.is('points') ? null : degree;
  }
}

/** Grey where the curve is not defined: outside [u_p, u_{m+1}]. */
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

/**
 * The segment whose four bases alone the plot shows (the uniform cubic's
 * step on one segment), else null.
 */
export function segmentShown(m: BSplineModel): number | null {
  return m.kind === 'uniform' && m.shown.is('segment') ? m.segment : null;
}

/** The samples of one basis function within [from, to] (interleaved u, N). */
function within(samples: Float64Array, from: number, to: number): Float64Array {
  const kept: number[] = [];
  for (let k = 0; k + 1 < samples.length; k += 2) {
    if (samples[k] >= from - 1e-9 && samples[k] <= to + 1e-9) kept.push(samples[k], samples[k + 1]);
  }
  return Float64Array.from(kept);
}

/**
 * The segment's step: the four basis functions that act on it, only over its
 * interval, where they are B0(t) … B3(t) of its local t, with their values at the cursor.
 */
function drawSegmentBases(painter: Painter, m: BSplineModel, i: number, info: DrawInfo): void {
  const theme = painter.theme;
  const { from, to } = m.segments[i];
  const color = painter.color(i);
  painter.polygon(
    [
      [from, 0],
      [to, 0],
      [to, 1],
      [from, 1],
    ],
    color,
    0.12,
  );
  const entries = [0, 1, 2, 3].map((k) => {
    const j = i + k;
    painter.polylineFlat(within(m.rows[m.degree][j], from, to), {
      color: painter.color(m.owner[j]),
      width: theme.sizes.curve,
    });
    return {
      y: m.basis[j],
      text: `B_${k}(t) = ${m.basis[j].toFixed(3)}`,
      color: painter.color(m.owner[j]),
    };
  });
  painter.segment([m.u, basisBounds(m).minY], [m.u, basisBounds(m).maxY], {
    color: theme.accent,
    width: theme.sizes.line,
  });
  for (const e of entries) painter.dot([m.u, e.y], e.color, theme.sizes.point);
  if (!info.thumbnail) valuesAt(painter, m.u, basisBounds(m), entries);
}

/**
 * The values at the cursor: above the plot, in the room the fit keeps there
 * (cursorValues), else boxed in the plot's top corner away from it (off the
 * curves they name).
 */
function valuesAt(
  painter: Painter,
  at: number,
  bounds: Bounds,
  entries: readonly { y: number; text: string; color: string }[],
): void {
  const top = painter.view.toScreen([bounds.minX, bounds.maxY])[1];
  const sorted = [...entries].sort((a, b) => b.y - a.y);
  valueColumn(painter, at, bounds, Math.max(top, 0), sorted);
}

/** N_{i,r}'s value at the cursor as the plot writes it. */
const valueText = (i: number, r: number, v: number) => `N_{${i},${r}} = ${v.toFixed(3)}`;

function drawBasis(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const bounds = basisBounds(m);
  const r = shownRow(m);
  painter.plotAxes(bounds, uStep(m), 0.25, isUniformPart(m.state.part) ? 's' : 'u', '');
  shadeOutside(painter, m, bounds);
  const seg = segmentIds.index(info.hover);
  if (seg !== null && m.segments[seg]) {
    const { from, to } = m.segments[seg];
    painter.polygon(
      [
        [from, 0],
        [to, 0],
        [to, 1],
        [from, 1],
      ],
      painter.color(seg),
      0.15,
    );
  }
  const segment = segmentShown(m);
  if (segment !== null) return drawSegmentBases(painter, m, segment, info);
  // Before its step shows them, the plot is only its axes.
  if (r === null) return;
  // A hovered control point (not its halo): its basis function drawn bold.
  const hovered = hoveredPoint(info.hover, false);
  const owner = (i: number) => (r === m.degree ? (m.owner[i] ?? i) : i);
  m.rows[r].forEach((samples, i) => {
    const strong = hovered !== null && hovered === owner(i);
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
  const row = m.table[r];
  const entries = row.flatMap((v, i) =>
    v > 0 ? [{ y: v, text: valueText(i, r, v), color: painter.color(owner(i)) }] : [],
  );
  for (const e of entries) painter.dot([u, e.y], e.color, theme.sizes.point);
  if (!info.thumbnail) valuesAt(painter, u, bounds, entries);
}

/**
 * What the basis plot and the knot strip are drawn from: everything but where
 * the control points are (their number sets m), so dragging one draws neither.
 */
export const drawnFromAllButPoints = ({ state, shown }: BSplineModel): readonly unknown[] => [
  state.part,
  state.t,
  state.degree,
  state.knots,
  state.weights,
  state.points.length,
  shown.key,
];

export const basisFigure: KitFigure<BSplineState, BSplineModel> = {
  id: 'basis',
  title: 'The B-spline basis functions, with the cursor at the parameter',
  kind: 'plot',
  weight: 1,
  bounds: basisBounds,
  // The values at the cursor above the plot, off the basis' peaks: one for
  // each basis function not 0 there, degree + 1 (the widest: the last's).
  cursorValues: (m) => ({
    count: m.degree + 1,
    widest: valueText(m.rows[m.degree].length - 1, m.degree, 0.5),
  }),
  draw: drawBasis,
  drawnFrom: drawnFromAllButPoints,
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
    const r = shownRow(m);
    if (r !== m.degree) return null;
    let best: string | null = null;
    let distance = tolerance * 2;
    m.rows[r].forEach((samples, i) => {
      for (let k = 0; k + 1 < samples.length; k += 2) {
        if (Math.abs(samples[k] - at[0]) > tolerance) continue;
        const d = Math.abs(samples[k + 1] - at[1]);
        if (d < distance && samples[k + 1] > 1e-6) {
          distance = d;
          // The control point's handle: hovering its basis function is hovering it.
          best = `p${m.owner[i] ?? i}`;
        }
      }
    });
    return best;
  },
};
