import { bernstein, binomial } from '../../math';
import { filled, texT, words } from '../../kit/format';
import { Script as KitScript, repeat, script, step } from '../../kit/script';
import { texNumber, texPoint } from '../../render/formula';
import type { BlendingModel } from './model';
import type { Nearest } from './passes';
import { type BlendingState, degree } from './state';
import { expansionTex, pointFormula, weightFormula } from './tex';

/** What the steps reveal, by name: the figures and the panel ask for these (through `drawn`). */
export type Reveal =
  // Bernstein's weights one by one
  | 'points'
  | 'weight'
  | 'point'
  | 'curve'
  // a comparison, starting from the whole Bézier picture
  | 'bezier'
  | 'data'
  | 'tangents'
  | 'basis'
  | 'ends'
  | 'spline'
  | 'hull'
  | 'atMu'
  // the symmetry μ → 1 − μ
  | 'functions'
  | 'mirror'
  | 'pair'
  | 'reversed'
  // interpolating or approximating: each curve, then which points it passes through
  | 'lagrangeCurve'
  | 'interpolating'
  | 'bezierCurve'
  | 'approximating';

type Script = KitScript<BlendingState, BlendingModel, Reveal>;

/** Where W(N, i, μ) is largest: μ = i/N, written as the lecture writes it. */
const peakOf = (i: number, n: number) => (i === 0 ? '0' : i === n ? '1' : `${i}/${n}`);

/**
 * The clicker's script: the points, each weight W(N, 0, μ) … W(N, N, μ) in
 * turn, their weighted sum P(μ), and the curve it traces.
 */
export const blendingScript: Script = script<BlendingState, BlendingModel, Reveal>(
  step(
    'points',
    ({ state }) => `The control points P0 … P${degree(state)} and their polygon`,
    ({ state }) => {
      const n = degree(state);
      return `P(\\mu) = \\sum_{i=0}^{${n}} W(${n},i,\\mu)\\,P_i`;
    },
  ),
  // Weight i is the (i + 1)-th repeat: P0's weight first.
  repeat(
    'weight',
    (state) => degree(state) + 1,
    ({ state, index }) => {
      const n = degree(state);
      const i = index - 1;
      return `The weight of P${i}: W(${n}, ${i}, μ), largest at μ = ${peakOf(i, n)}`;
    },
    ({ state: { mu }, model: { n }, index }) => {
      const i = index - 1;
      return `${filled(weightFormula(n, i, mu))} = ${bernstein(n, i, mu).toFixed(4)}`;
    },
  ),
  step('point', 'P(μ): the control points averaged with these weights', ({ state, model }) =>
    filled(pointFormula(state.mu, model.weights, state.p, model.point)),
  ),
  step('curve', 'As μ runs from 0 to 1, P(μ) traces the Bézier curve', ({ model: { n } }) =>
    expansionTex(n, 4),
  ),
);

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

/** The compared functions' values at μ and their sum, as TeX. */
const valuesAtMu = (m: BlendingModel) => {
  const c = m.compared!;
  const mu = texT(m.state.mu);
  const values = c.atMu.map((v, k) => `${c.labels[k]}(${mu}) = ${texNumber(v, 4)}`);
  return `${values.join(',\\ ')},\\quad \\textstyle\\sum = ${words(c.sum)}`;
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
export const hermiteScript: Script = script<BlendingState, BlendingModel, Reveal>(
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
    'Then the end gradients of the cubic: 3(P1 − P0) at the start, 3(P3 − P2) at the end',
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
    ({ state }) => `At μ = ${texT(state.mu)}, the four Hermite weights give the same point P(μ)`,
    ({ model }) => valuesAtMu(model),
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
export const bsplineScript: Script = script<BlendingState, BlendingModel, Reveal>(
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
export const lagrangeScript: Script = script<BlendingState, BlendingModel, Reveal>(
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

/** W(N, i, μ) = C(N, i) μⁱ (1 − μ)ᴺ⁻ⁱ at these numbers, and the same with μ and 1 − μ swapped. */
function pairFormula(n: number, i: number, mu: number): string {
  const a = texT(mu);
  const b = texT(1 - mu);
  const j = n - i;
  const value = bernstein(n, i, mu).toFixed(4);
  return `W(${n},${i},${a}) = ${binomial(n, i)}\\cdot ${a}^{${i}}\\,${b}^{${j}} = ${binomial(n, j)}\\cdot ${b}^{${j}}\\,${a}^{${i}} = W(${n},${j},${b}) = ${value}`;
}

/** The pairs (i, N − i) with i ≤ N − i: one press each. */
export const pairCount = (state: BlendingState) => Math.floor(degree(state) / 2) + 1;

/**
 * The symmetry of the blending functions under μ → 1 − μ (the lecture
 * slides: "symmetric under u → (1 − u)"): the functions, the mirrored
 * cursor, each pair W(N, i, μ) = W(N, N − i, 1 − μ) with the numbers of μ,
 * and what it means for the curve: reversed points, the same curve backwards.
 */
export const symmetryScript: Script = script<BlendingState, BlendingModel, Reveal>(
  step(
    'functions',
    ({ state }) =>
      `The ${degree(state) + 1} blending functions of degree ${degree(state)}, with the cursor at μ = ${texT(state.mu)}`,
    ({ state }) =>
      `W(${degree(state)},i,\\mu) = \\binom{${degree(state)}}{i}\\mu^{i}(1-\\mu)^{${degree(state)}-i}`,
  ),
  step(
    'mirror',
    ({ state }) => `Mirror μ in ½: a second cursor at 1 − μ = ${texT(1 - state.mu)}`,
    ({ state }) => `1 - \\mu = 1 - ${texT(state.mu)} = ${texT(1 - state.mu)}`,
  ),
  repeat(
    'pair',
    pairCount,
    ({ state, index }) => {
      const n = degree(state);
      const i = index - 1;
      const value = words(bernstein(n, i, state.mu));
      return i === n - i
        ? `W(${n}, ${i}, μ) = W(${n}, ${i}, 1 − μ) = ${value}: the middle function is its own mirror image`
        : `W(${n}, ${i}, μ) = W(${n}, ${n - i}, 1 − μ) = ${value}: swapping μ and 1 − μ swaps P${i}'s weight and P${n - i}'s`;
    },
    ({ state, index }) => pairFormula(degree(state), index - 1, state.mu),
  ),
  step(
    'reversed',
    'So P(1 − μ) weights the points in reverse order: reversed control points trace the same curve backwards',
    ({ state, model }) => {
      const n = degree(state);
      return `P(${texT(1 - state.mu)}) = \\sum_{i=0}^{${n}} W(${n},i,${texT(state.mu)})\\,P_{${n}-i} = ${texPoint(model.mirrored, 3)}`;
    },
  ),
);

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
export const passesScript: Script = script<BlendingState, BlendingModel, Reveal>(
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

/**
 * Bernstein's script, or the symmetry's when the mirror is chosen: the
 * lesson's script for every state no Compare scene's script covers. (The
 * symmetry would be a scene of its own, but the recorded links pin the list
 * of scenes; the kit picks a scene's script only for a declared scene.)
 */
class BernsteinOrSymmetry extends KitScript<BlendingState, BlendingModel, Reveal> {
  constructor() {
    super([]);
  }
  private of = (state: BlendingState) =>
    state.comparison === 'mirror' ? symmetryScript : blendingScript;
  override lastStep(state: BlendingState) {
    return this.of(state).lastStep(state);
  }
  override shown(state: BlendingState, k: number) {
    return this.of(state).shown(state, k);
  }
  override caption(state: BlendingState, model: BlendingModel, k: number) {
    return this.of(state).caption(state, model, k);
  }
  override formula(state: BlendingState, model: BlendingModel, k: number) {
    return this.of(state).formula(state, model, k);
  }
  override stepOf(state: BlendingState, name: Reveal, index = 1) {
    return this.of(state).stepOf(state, name, index);
  }
}

export const lessonScript: Script = new BernsteinOrSymmetry();

/** The script a state walks: one per comparison, Bernstein's alone without one. */
export function scriptOf(state: BlendingState): Script {
  switch (state.comparison) {
    case 'none':
      return blendingScript;
    case 'hermite':
      return hermiteScript;
    case 'bspline':
      return bsplineScript;
    case 'lagrange':
      return lagrangeScript;
    case 'mirror':
      return symmetryScript;
    case 'interpolating':
      return passesScript;
  }
}

/** After an edit that changes the script or its length: shown to its end, it stays at the end. */
export function keepShownToEnd(before: BlendingState, after: BlendingState): BlendingState {
  const lastBefore = scriptOf(before).lastStep(before);
  const lastAfter = scriptOf(after).lastStep(after);
  const step = before.step >= lastBefore ? lastAfter : Math.min(before.step, lastAfter);
  return { ...after, step };
}
