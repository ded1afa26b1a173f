/**
 * The first three scenes: a curve plotted as segments, uniform sampling
 * against adaptive flattening, and the flattening's subdivision stepped.
 */
import { count } from '../../app/fields';
import { texNumber, trimmed } from '../../kit/format';
import { type StepAt, repeat, script, step } from '../../kit/script';
import { type RasterModel, SAME_ERROR_MAX } from './model';
import { type Reveal, piecePresses, piecesAt } from './reveals';
import { type RasterState, segmentsOf } from './state';

type At = StepAt<RasterState, RasterModel>;

const num = (v: number, digits = 2) => texNumber(v, digits);
/** A length in units of the control points, in pixels of the raster. */
const px = (m: RasterModel, units: number) => units * m.state.zoom;

/** Plot the curve: compute points on it, join them, see how far the segments stray. */
export const plotScript = script<RasterState, RasterModel, Reveal>(
  step(
    'points',
    ({ model: m }) =>
      `Given: the ${m.state.points.length} control points of a Bézier curve of degree ${m.degree}. Task: plot the curve.`,
  ),
  step(
    'samples',
    ({ state }) => {
      const n = segmentsOf(state);
      return `Compute ${n + 1} points P(k/${n}) on the curve, k = 0 … ${n}: the only exact points we will have.`;
    },
    ({ state }) => {
      const n = segmentsOf(state);
      return `P\\!\\left(\\tfrac{k}{${n}}\\right),\\quad k = 0,1,\\dots,${n}`;
    },
  ),
  step(
    'polyline',
    ({ state }) =>
      `Join them by ${count(segmentsOf(state), 'straight segment')}: this polyline is what the screen draws.`,
  ),
  step('curve', 'The true curve: between the computed points it bends away from the segments.'),
  step(
    'gap',
    ({ state, model: m }) => {
      const d = m.uniform.deviation;
      return `Largest gap ${num(px(m, d.distance))} px, at t = ${num(d.t, 3)} in segment ${d.piece + 1} of ${segmentsOf(state)}.`;
    },
    ({ model: m }) =>
      `\\max_t \\operatorname{dist}\\big(P(t),\\ \\text{segment}\\big) = ${num(px(m, m.uniform.deviation.distance))}\\ \\text{px at } t = ${num(m.uniform.deviation.t, 3)}`,
  ),
);

/** Both polylines' gaps against τ: the formula of the compare scene's middle steps. */
const gaps = ({ state, model: m }: At) =>
  `\\text{uniform } ${segmentsOf(state)}: ${num(px(m, m.uniform.deviation.distance))}\\ \\text{px} \\qquad \\text{adaptive } ${m.adaptive.points.length - 1}: ${num(px(m, m.adaptive.deviation.distance))}\\ \\text{px} \\le \\tau = ${num(state.tolerance)}`;

/** Uniform or adaptive: the same curve, the segments spent where they are needed or evenly. */
export const compareScript = script<RasterState, RasterModel, Reveal>(
  step(
    'twice',
    ({ state }) =>
      // The figures sit side by side on a wide screen and one under the
      // other on a phone: the caption names them by their titles.
      `The same curve twice: “Uniform” samples it at even steps of t, “Adaptive” flattens it to τ = ${num(state.tolerance)} px.`,
  ),
  step(
    'uniform',
    ({ state, model: m }) =>
      `Uniform, ${count(segmentsOf(state), 'segment')}: largest gap ${num(px(m, m.uniform.deviation.distance))} px (τ = ${num(state.tolerance)} px).`,
  ),
  step(
    'adaptive',
    ({ state, model: m }) =>
      `Adaptive to τ = ${num(state.tolerance)} px: ${count(m.adaptive.points.length - 1, 'segment')}, largest gap ${num(px(m, m.adaptive.deviation.distance))} px, the short ones where the curve bends.`,
    gaps,
  ),
  step(
    'sameGap',
    ({ model: m }) =>
      `For the same gap of ${num(px(m, m.adaptive.deviation.distance))} px, uniform sampling needs ${m.sameError ? count(m.sameError.points.length - 1, 'segment') : `more than ${SAME_ERROR_MAX} segments`}.`,
    gaps,
  ),
  // The caption counts the polyline the figure draws at this step (m.bound),
  // not the one of the step before (the same gap as adaptive: fewer segments).
  step(
    'bound',
    ({ model: m }) =>
      `Without measuring, uniform sampling must plan for the sharpest bend: ${count(m.bound.points.length - 1, 'segment')} to be sure of τ; they stray ${num(px(m, m.bound.deviation.distance))} px.`,
    ({ state, model: m }) =>
      `N = \\left\\lceil \\sqrt{\\frac{n(n-1)\\,\\max\\|\\Delta^2 P\\|}{8\\,\\tau}} \\right\\rceil = \\left\\lceil \\sqrt{\\frac{${num(px(m, m.tree[0].flatness))}}{${num(state.tolerance)}}} \\right\\rceil = ${m.bound.points.length - 1}`,
  ),
);

/** The flatness test of the whole curve, the question the subdivision asks and answers. */
const flatness = ({ state }: At) =>
  `\\tfrac{n(n-1)}{8}\\max_i \\|P_{i+2} - 2P_{i+1} + P_i\\| \\le \\tau = ${num(state.tolerance)}`;

/** The piece the `index`-th press visits last (of `times` presses before "done"). */
const visited = ({ model: m, index, times }: At) =>
  m.tree[piecesAt(m.tree.length, index, times + 1) - 1];

/** Flatten by subdivision: each piece flat enough is a segment, the others are halved. */
export const subdivideScript = script<RasterState, RasterModel, Reveal>(
  step(
    'question',
    ({ state }) =>
      `Does the control polygon bend so little that the curve is within τ = ${num(state.tolerance)} px of its chord? If not, split at t = ½.`,
    flatness,
  ),
  repeat(
    'pieces',
    piecePresses,
    (at) => {
      const { model: m } = at;
      const node = visited(at);
      // Halves of halves: t0 and t1 are k/2ᵈ, exact in four decimals to depth 4.
      const range = `t ∈ [${trimmed(node.t0, 4)}, ${trimmed(node.t1, 4)}]`;
      const flatness = num(px(m, node.flatness));
      if (node.split)
        return `Piece ${range}: flatness ${flatness} px > τ, so split it at its middle.`;
      // Kept at the depth limit although not flat enough (flattenBezier stops there too).
      if (node.cut)
        return `Piece ${range}: flatness ${flatness} px > τ, but as deep as the flattening goes, so draw it as one segment.`;
      return `Piece ${range}: flatness ${flatness} px ≤ τ, so draw it as one segment.`;
    },
    (at) => {
      const { state, model: m } = at;
      const node = visited(at);
      return `\\tfrac{${m.degree}\\cdot${m.degree - 1}}{8}\\max\\|\\Delta^2 P\\| = ${num(px(m, node.flatness))}\\ ${node.split || node.cut ? '>' : '\\le'}\\ ${num(state.tolerance)}`;
    },
  ),
  step(
    'done',
    ({ model: m }) =>
      `Done: ${count(m.adaptive.points.length - 1, 'segment')} from ${count(m.tree.length, 'piece')} looked at, halved at most ${count(Math.max(...m.tree.map((node) => node.depth)), 'time')}.`,
    flatness,
  ),
);
