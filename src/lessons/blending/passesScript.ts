import { words } from '../../kit/format';
import { script, step } from '../../kit/script';
import { texNumber, texPoint } from '../../render/formula';
import type { BlendingModel } from './model';
import type { Nearest } from './passes';
import type { BlendingScript, Reveal } from './reveals';
import { type BlendingState, degree } from './state';
import { expansionTex } from './tex';

// The last scene's script, interpolating or approximating: how far each
// control point is from the Lagrange curve, then from the Bézier curve.

/** A list in words: "P0 and P3", "P1, P2 and P4". */
const listed = (items: readonly string[]) =>
  items.length <= 1
    ? (items[0] ?? '')
    : `${items.slice(0, -1).join(', ')} and ${items[items.length - 1]}`;
const pointNames = (indices: readonly number[]) => listed(indices.map((i) => `P${i}`));

/** Each point's distance to a curve, as TeX: `0,\\ 0.714,\\ 0.714,\\ 0`. */
const distancesTex = (near: readonly Nearest[]) =>
  near.map((q) => texNumber(q.distance, 3)).join(',\\ ');

/** The row of a curve's distances: d(Pᵢ, L) = min over μ of |L(μ) − Pᵢ|, then the numbers. */
const distanceRow = (curve: string, near: readonly Nearest[]) =>
  `d(P_i, ${curve}) = \\min_\\mu |${curve}(\\mu) - P_i|:\\quad ${distancesTex(near)}`;

/** What the Bézier curve passes through, and how far it stays from the rest. */
function approximatingCaption(m: BlendingModel): string {
  const { onBezier, bezier } = m.passes!;
  const on = onBezier.flatMap((yes, i) => (yes ? [i] : []));
  const off = onBezier.flatMap((yes, i) => (yes ? [] : [i]));
  if (off.length === 0)
    return 'Here the Bézier curve passes through every control point too: distance 0 from each';
  const far = listed(off.map((i) => words(bezier[i].distance)));
  const through = on.length
    ? `passes through ${pointNames(on)} only`
    : 'passes through none of them';
  const stay = off.length === 1 ? 'stays' : 'stay';
  return `Approximating: the Bézier curve ${through}; ${pointNames(off)} ${stay} ${far} away, shaping it without lying on it`;
}

/**
 * Interpolating or approximating (the lecture slides: interpolating splines
 * "actually go through the points"; approximating ones have control points
 * that "define the shape of the curve, but do not necessarily lie on the
 * curve"): the points, the Lagrange curve and the distance of each point to
 * it, then the Bézier curve and the same.
 */
export const passesScript: BlendingScript = script<BlendingState, BlendingModel, Reveal>(
  step(
    'points',
    ({ state }) =>
      `The control points P0 … P${degree(state)}, for two curves: does each pass through them?`,
    ({ state }) => state.p.map((q, i) => `P_{${i}} = ${texPoint(q, 2)}`).join(',\\ '),
  ),
  step(
    'lagrangeCurve',
    'Dashed: the Lagrange curve of these points, with its weights Lᵢ(μ)',
    () => 'L(\\mu) = \\sum_i L_i(\\mu)\\,P_i,\\qquad L_i(\\tfrac{j}{N}) = [\\,i = j\\,]',
  ),
  step(
    'interpolating',
    ({ model }) =>
      model.passes!.onLagrange.every(Boolean)
        ? 'Interpolating: the Lagrange curve passes through every control point, each at distance 0'
        : `The Lagrange curve comes within ${words(Math.max(...model.passes!.lagrange.map((q) => q.distance)))} of every control point`,
    ({ model }) => distanceRow('L', model.passes!.lagrange),
  ),
  step(
    'bezierCurve',
    ({ state }) =>
      `The Bézier curve of the same points, with its weights W(${degree(state)}, i, μ)`,
    ({ model: { n } }) => expansionTex(n, 4),
  ),
  step(
    'approximating',
    ({ model }) => approximatingCaption(model),
    ({ model }) =>
      `\\begin{aligned}${distanceRow('L', model.passes!.lagrange)}\\\\ ${distanceRow('P', model.passes!.bezier)}\\end{aligned}`,
  ),
);
