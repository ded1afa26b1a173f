import { sub, texT, texTogether, words } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import type { Point } from '../../math';
import type { DeCasteljauModel } from './model';
import { type DeCasteljauState, degree } from './state';

/** What the pseudocode's steps reveal, by name. */
export type PseudocodeReveal = 'input' | 'copy' | 'compute' | 'return' | 'plot';

/**
 * The construction as a program, in the order of the continuation notes'
 * levels x_i^(r) (the lecture notes write it as a recursion, see notes.ts).
 * Each line: its number (as captions and formulas name it) and its text.
 */
export const LISTING: readonly (readonly [number, string])[] = [
  [0, 'deCasteljau(P₀ … Pₙ, t)'],
  [1, 'for i = 0 … n:  P₀,ᵢ = Pᵢ'],
  [2, 'for r = 1 … n:'],
  [3, '  for i = 0 … n − r:'],
  [4, '    Pᵣ,ᵢ = (1−t)·Pᵣ₋₁,ᵢ + t·Pᵣ₋₁,ᵢ₊₁'],
  [5, 'return Pₙ,₀'],
  [6, 'drawCurve: for j = 0 … L:\n  plot deCasteljau(P₀ … Pₙ, j/L)'],
];

/** The lines each step runs (the listing's numbers). */
export const LINES_RUN: Readonly<Record<PseudocodeReveal, readonly number[]>> = {
  input: [0],
  copy: [1],
  compute: [2, 3, 4],
  return: [5],
  plot: [6],
};

/** drawCurve's L: the curve is plotted at t = 0, 1/L, …, 1. */
export const PLOT_STEPS = 10;

/** One press per point while that stays short (up to degree 4: 10 points), else one per level. */
export const onePerPoint = (n: number) => (n * (n + 1)) / 2 <= 10;

/** How many presses line 4 takes: one per point, or one per level. */
const computeTimes = (state: DeCasteljauState) => {
  const n = degree(state);
  return onePerPoint(n) ? (n * (n + 1)) / 2 : n;
};

/** The points P_{r,i} the `index`-th press of line 4 computes (1-based), in the loops' order. */
export function computedBy(n: number, index: number): [number, number][] {
  if (!onePerPoint(n)) return Array.from({ length: n - index + 1 }, (_, i) => [index, i]);
  let k = index;
  for (let r = 1; r <= n; r++) {
    if (k <= n - r + 1) return [[r, k - 1]];
    k -= n - r + 1;
  }
  return [];
}

/** P_{r,i} in TeX, P₁,₀ in words. */
const name = (r: number, i: number) => `P_{${r},${i}}`;
const nameWords = (r: number, i: number) => `P${sub(r)},${sub(i)}`;

/** A point as a hand computation writes it: (0.5, 1), up to four decimals, written together. */
export const exactPoint = (p: readonly number[]) => texTogether(p, 4);

/** Line 4 for one point, with the numbers: P_{1,0} = 0.4·(0, 0) + 0.6·(1, 2) = (0.6, 1.2). */
export function cutTex(levels: readonly Point[][], t: number, r: number, i: number): string {
  return `${name(r, i)} = ${texT(1 - t)}\\cdot${exactPoint(levels[r - 1][i])} + ${texT(t)}\\cdot${exactPoint(levels[r - 1][i + 1])} = ${exactPoint(levels[r][i])}`;
}

const pointList = (points: readonly Point[], label: (i: number) => string) =>
  points.length > 5
    ? `${label(0)} = ${exactPoint(points[0])},\\ \\dots,\\ ${label(points.length - 1)} = ${exactPoint(points[points.length - 1])}`
    : points.map((q, i) => `${label(i)} = ${exactPoint(q)}`).join(',\\ ');

/** The pseudocode run line by line on the current points, every number shown. */
export const pseudocode = script<DeCasteljauState, DeCasteljauModel, PseudocodeReveal>(
  step(
    'input',
    ({ state }) =>
      `The input: ${degree(state) + 1} control points P₀ … P${sub(degree(state))} and t = ${words(state.t)}`,
    ({ state }) =>
      `\\text{0: deCasteljau}(P_0,\\dots,P_{${degree(state)}};\\ t = ${texT(state.t)}),\\quad ${pointList(state.p, (i) => `P_{${i}}`)}`,
  ),
  step(
    'copy',
    'Line 1 copies the control points into level 0: the control polygon',
    ({ state }) => `\\text{1: } P_{0,i} = P_i:\\quad ${pointList(state.p, (i) => name(0, i))}`,
  ),
  repeat(
    'compute',
    computeTimes,
    ({ state, index }) => {
      const n = degree(state);
      const points = computedBy(n, index);
      const [r, i] = points[0];
      const t = words(state.t);
      if (points.length > 1)
        return `r = ${r}: lines 3 and 4 run i = 0 … ${n - r}, cutting every edge of level ${r - 1} at t = ${t}`;
      return `r = ${r}, i = ${i}: line 4 cuts the edge ${nameWords(r - 1, i)} ${nameWords(r - 1, i + 1)} at t = ${t}, giving ${nameWords(r, i)}`;
    },
    ({ state, model: { levels }, index }) => {
      const points = computedBy(degree(state), index);
      const [r, i] = points[0];
      if (points.length === 1)
        return `\\text{4: } r = ${r},\\ i = ${i}:\\quad ${cutTex(levels, state.t, r, i)}`;
      const last = points.length - 1;
      return `\\text{4: } r = ${r}:\\quad ${cutTex(levels, state.t, r, 0)},\\ \\dots,\\ ${name(r, last)} = ${exactPoint(levels[r][last])}`;
    },
  ),
  step(
    'return',
    ({ state }) =>
      `Line 5 returns P${sub(degree(state))},₀: the point P(t) on the curve at t = ${words(state.t)}`,
    ({ state, model: { levels, n } }) =>
      `\\text{5: return } ${name(n, 0)} = P(${texT(state.t)}) = ${exactPoint(levels[n][0])}`,
  ),
  step(
    'plot',
    `Line 6 runs it again for t = 0, 1/${PLOT_STEPS}, …, 1 and plots each point: the curve`,
    ({ model: { plotted } }) =>
      `\\text{6: plot } P(j/${PLOT_STEPS}),\\ j = 0,\\dots,${PLOT_STEPS}:\\quad P(0) = ${exactPoint(plotted[0])},\\ P(${texT(1 / PLOT_STEPS)}) = ${exactPoint(plotted[1])},\\ \\dots,\\ P(1) = ${exactPoint(plotted[PLOT_STEPS])}`,
  ),
);
