import { sub, texNumber, trimmed } from '../../kit/format';
import { script, step } from '../../kit/script';
import { type KnotPoint, nearestControl } from './meaningsGeometry';
import type { MeaningsModel } from './model';
import { n3, pt } from './notation';
import { KNOT_WORDS } from './notes';
import type { BSplineState } from './state';

/** What the steps of the two meanings of “knots” reveal, by name. */
export type MeaningsReveal = 'points' | 'values' | 'joins' | 'lecture' | 'controls' | 'meet';

/** A knot point's name in a caption and on the figure: P(u₄). */
export const knotPointName = (k: KnotPoint) => `P(u${sub(k.index)})`;

/** The knot points that land on a control point: where the two meanings are one spot. */
const meeting = (m: MeaningsModel) => m.knotPoints.filter((k) => k.on !== null);

/** The knot points' names, P(u₃) … P(u₇) (the table under the words has each). */
function joinNames(m: MeaningsModel): string {
  const names = m.knotPoints.map(knotPointName);
  return names.length <= 2 ? names.join(' and ') : `${names[0]} … ${names[names.length - 1]}`;
}

function meetCaption(m: MeaningsModel): string {
  const meet = meeting(m);
  if (meet.length === 0) {
    const { knot, point } = nearestControl(m.knotPoints, m.state.points);
    return `No curve point at a knot lands on a control point here: the nearest pair, ${knotPointName(knot)} and P${point}, is marked with its distance`;
  }
  const said = meet.map((k) => `${knotPointName(k)} = P${k.on}`);
  const spots =
    said.length === 1 ? said[0] : `${said.slice(0, -1).join(', ')} and ${said[said.length - 1]}`;
  return `Both meanings on one spot: ${spots}, where the curve’s point at a knot value is a control point`;
}

/** The nearest a knot's curve point comes to a control point, or each one that lands on one. */
function meetTex(m: MeaningsModel): string {
  const meet = meeting(m);
  if (meet.length > 0)
    return meet.map((k) => `P(u_{${k.index}}) = P_{${k.on}} = ${pt(k.at)}`).join(',\\quad ');
  const { knot, point, distance } = nearestControl(m.knotPoints, m.state.points);
  return `\\text{nearest: } \\lvert P(u_{${knot.index}}) - P_{${point}} \\rvert = ${n3(distance)}`;
}

/** Up to this many knot points the table has a column each; beyond, its first three and last two. */
const FULL_COLUMNS = 6;

/**
 * Each knot value u_j and the curve's point P(u_j) there, as a two-row table:
 * one row a column, five rows of P(u_j) = P(u) = (x, y) would crowd the figure (#19).
 */
export function joinsTex(m: MeaningsModel): string {
  const all = m.knotPoints;
  const shown: (KnotPoint | null)[] =
    all.length <= FULL_COLUMNS ? all : [...all.slice(0, 3), null, ...all.slice(-2)];
  const cell = (write: (k: KnotPoint) => string, dots: string) =>
    shown.map((k) => (k === null ? dots : write(k))).join(' & ');
  const values = cell((k) => `u_{${k.index}} = ${trimmed(k.u, 3)}`, '\\cdots');
  const points = cell((k) => pt(k.at), '\\cdots');
  return `\\begin{array}{r|${'c'.repeat(shown.length)}} u & ${values} \\\\ \\hline P(u) & ${points}\\end{array}`;
}

/**
 * “Knots” as the documents use the word, on one curve: the parameter values
 * on the strip (the continuation notes, this app), the curve's points at them
 * where its pieces join (the lecture notes' patches), the control points (the
 * lecture notes' Bézier curves, the “Splines” slides), and where they coincide.
 */
export const meaningsScript = script<BSplineState, MeaningsModel, MeaningsReveal>(
  step('points', ({ state }) => {
    const n = state.points.length;
    return `The m + 1 = ${n} control points P0 … P${n - 1} of a B-spline of degree ${state.degree}`;
  }),
  step(
    'values',
    ({ model: m }) =>
      `Knots in the continuation notes and here: the parameter values u0 ≤ … ≤ u${m.knots.length - 1} on the strip; the curve P(u) runs over them`,
    ({ model: m }) => `u = (${m.knots.map((v) => texNumber(v, 2)).join(',\\ ')})`,
  ),
  step(
    'joins',
    ({ model: m }) =>
      `At the knot values the curve’s pieces join: ${joinNames(m)}, each named after its u on the strip`,
    ({ model }) => joinsTex(model),
  ),
  step('lecture', `The lecture notes call such points knots: “${KNOT_WORDS.lectureJoin}”`),
  step(
    'controls',
    ({ state }) =>
      `The “Splines” slides’ “${KNOT_WORDS.splineSlides}”, like the lecture notes’ Bézier curve that “${KNOT_WORDS.lectureBezier}”: here P0 … P${state.points.length - 1}`,
  ),
  step(
    'meet',
    ({ model }) => meetCaption(model),
    ({ model }) => meetTex(model),
  ),
);
