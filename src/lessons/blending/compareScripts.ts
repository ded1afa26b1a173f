import { termRow, texT, words } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import { texNumber, texPoint } from '../../render/formula';
import { peakOf } from './bernsteinScript';
import type { BlendingModel } from './model';
import type { BlendingScript, Reveal } from './reveals';
import { type BlendingState, degree } from './state';

// The three Compare scenes' scripts: Hermite's functions, the uniform cubic
// B-spline's and Lagrange's, each set beside the Bézier picture it starts from.

/** Step 0 of every comparison: what the Bernstein scenes built, all at once. */
const bezier = step<BlendingState, BlendingModel, Reveal>(
  'bezier',
  ({ state }) =>
    `The control points P0 … P${degree(state)}, their Bézier curve and Bernstein weights, to compare with`,
  ({ state }) => {
    const n = degree(state);
    return `P(\\mu) = \\sum_{i=0}^{${n}} W(${n},i,\\mu)\\,P_i`;
  },
);

/** The compared function k (the k-th repeat of 'basis'), its name in words. */
const plainName = (m: BlendingModel, k: number) =>
  m.compared!.labels[k].replace(/_\{?([^}]*)\}?/, '$1');

/**
 * The compared functions' values at μ and what they sum to, as TeX: all of
 * them, or (Hermite's) only those that weight points, the others weighting
 * gradients: H₀ + H₁ = 1, where the four would sum to a number of no meaning.
 */
const valuesAtMu = (m: BlendingModel, weightingPoints = m.compared!.atMu.length) => {
  const c = m.compared!;
  const mu = texT(m.state.mu);
  const values = c.atMu.map((v, k) => `${c.labels[k]}(${mu}) = ${texNumber(v, 4)}`);
  const row = termRow(values);
  if (weightingPoints === c.atMu.length)
    return `${row},\\allowbreak\\quad {\\textstyle\\sum = ${words(c.sum)}}`;
  const points = c.atMu.slice(0, weightingPoints);
  const sum = points.reduce((a, b) => a + b, 0);
  return `${row},\\allowbreak\\quad {${c.labels.slice(0, weightingPoints).join(' + ')} = ${words(sum)}}`;
};

const HERMITE_ROLES = [
  'weights the start point P0',
  'weights the end point',
  'weights the start gradient',
  'weights the end gradient, and is below zero on the whole of (0, 1)',
];

/**
 * Compared with Hermite's functions: the data of the patch (its end points,
 * then, for the cubic, its end gradients 3(P1 − P0) and 3(P3 − P2)), each
 * function H0 … H3, and the same point P(μ) from them.
 */
export const hermiteScript: BlendingScript = script<BlendingState, BlendingModel, Reveal>(
  bezier,
  step(
    'data',
    ({ state }) => `Hermite's data, first the end points: P0 and P${degree(state)}`,
    ({ state }) =>
      `P_0 = ${texPoint(state.p[0], 2)},\\quad P_{${degree(state)}} = ${texPoint(state.p[degree(state)], 2)}`,
  ),
  repeat(
    'tangents',
    (state) => (degree(state) === 3 ? 1 : 0),
    'Then the end gradients of the cubic: 3(P1 − P0) at the start, 3(P3 − P2) at the end, drawn at half length',
    ({ model }) => {
      const [[from0, tip0], [from1, tip1]] = model.compared!.arrows;
      const d = (a: readonly number[], b: readonly number[]) =>
        texPoint([b[0] - a[0], b[1] - a[1]], 2);
      return `D_0 = 3(P_1 - P_0) = ${d(from0, tip0)},\\quad D_3 = 3(P_3 - P_2) = ${d(from1, tip1)}`;
    },
  ),
  repeat(
    'basis',
    () => 4,
    ({ model, index }) => {
      const role = HERMITE_ROLES[index - 1].replace('end point', `end point P${model.n}`);
      return `${plainName(model, index - 1)} ${role}`;
    },
    ({ model, index }) => `${model.compared!.labels[index - 1]}(\\mu) = ${HERMITE_TEX[index - 1]}`,
  ),
  step(
    'atMu',
    ({ state }) =>
      `At μ = ${texT(state.mu)}, the four Hermite weights give the same point P(μ); the two that weight points sum to 1`,
    ({ model }) => valuesAtMu(model, 2),
  ),
);

/** H0 … H3 of the cubic patch (equation 7 of the lecture, multiplied out). */
const HERMITE_TEX = [
  '2\\mu^3 - 3\\mu^2 + 1',
  '-2\\mu^3 + 3\\mu^2',
  '\\mu^3 - 2\\mu^2 + \\mu',
  '\\mu^3 - \\mu^2',
];

const BSPLINE_TEX = [
  '\\tfrac{1}{6}(1-\\mu)^3',
  '\\tfrac{1}{6}(3\\mu^3 - 6\\mu^2 + 4)',
  '\\tfrac{1}{6}(-3\\mu^3 + 3\\mu^2 + 3\\mu + 1)',
  '\\tfrac{1}{6}\\mu^3',
];

/**
 * Compared with the uniform cubic B-spline: its four functions, where its
 * curve starts and ends (not at P0 and PN), the curve, and its point at μ.
 */
export const bsplineScript: BlendingScript = script<BlendingState, BlendingModel, Reveal>(
  bezier,
  repeat(
    'basis',
    () => 4,
    ({ model, index }) =>
      `B${index - 1}: never negative, and at most ${words(model.compared!.highest[index - 1])}, so it never takes a point whole`,
    ({ model, index }) => `${model.compared!.labels[index - 1]}(\\mu) = ${BSPLINE_TEX[index - 1]}`,
  ),
  repeat(
    'ends',
    (state) => (degree(state) >= 3 ? 1 : 0),
    'The B-spline starts at (P0 + 4P1 + P2) / 6 and ends likewise: not at P0 or at the last point',
    ({ model }) => {
      const curve = model.compared!.curve!;
      const n = model.n;
      return `\\tfrac{1}{6}(P_0 + 4P_1 + P_2) = ${texPoint(curve[0], 3)},\\quad \\tfrac{1}{6}(P_{${n - 2}} + 4P_{${n - 1}} + P_{${n}}) = ${texPoint(curve[curve.length - 1], 3)}`;
    },
  ),
  repeat(
    'spline',
    (state) => (degree(state) >= 3 ? 1 : 0),
    'Dashed: the uniform B-spline of these points, inside their hull and through none of them',
    () => 'B(\\mu) = B_0 P_i + B_1 P_{i+1} + B_2 P_{i+2} + B_3 P_{i+3}',
  ),
  step(
    'atMu',
    ({ state }) => `At μ = ${texT(state.mu)}, the four B-spline weights, never negative, sum to 1`,
    ({ model }) => valuesAtMu(model),
  ),
);

/**
 * Compared with Lagrange's functions on equally spaced nodes: each Lᵢ, the
 * curve through every point, the hull it leaves, and its point at μ.
 */
export const lagrangeScript: BlendingScript = script<BlendingState, BlendingModel, Reveal>(
  bezier,
  repeat(
    'basis',
    (state) => degree(state) + 1,
    ({ model, index }) => {
      const i = index - 1;
      return `L${i}: 1 at its own node μ = ${peakOf(i, model.n)}, 0 at the others, and negative in places`;
    },
    ({ model, index }) => {
      const i = index - 1;
      return `L_{${i}}(\\mu) = \\prod_{j \\ne ${i}} \\frac{\\mu - j/${model.n}}{${i}/${model.n} - j/${model.n}}`;
    },
  ),
  step(
    'spline',
    'Dashed: the Lagrange curve Σ Lᵢ(μ) Pᵢ, through every control point',
    () => 'L(\\mu) = \\sum_i L_i(\\mu)\\,P_i,\\qquad L_i(\\tfrac{j}{N}) = [\\,i = j\\,]',
  ),
  step(
    'hull',
    ({ model }) =>
      `The convex hull of the control points: ${Math.round(100 * (model.compared!.outside ?? 0))}% of the Lagrange curve lies outside it`,
    () =>
      '\\text{Bézier: } W(N,i,\\mu) \\ge 0,\\ \\textstyle\\sum_i W = 1 \\;\\Rightarrow\\; P(\\mu) \\text{ in the hull}',
  ),
  step(
    'atMu',
    ({ state }) => `At μ = ${texT(state.mu)}, the Lagrange weights: some are negative`,
    ({ model }) => valuesAtMu(model),
  ),
);
