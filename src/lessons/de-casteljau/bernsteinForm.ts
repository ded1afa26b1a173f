import { sub, texResidue, texT, words } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import { binomial } from '../../math';
import type { DeCasteljauModel } from './model';
import { exactPoint } from './pseudocode';
import { type DeCasteljauState, degree } from './state';

/** What the steps of the expansion reveal, by name. */
export type BernsteinReveal = 'points' | 'blend' | 'same';

/** Up to this level every term is written out; beyond, the sum and its ends. */
const WRITTEN_OUT = 4;

/** W(r, j, t) as the lecture notes' table writes it: 3t(1 − t)², t³, (1 − t)². */
export function weightTex(r: number, j: number): string {
  const c = binomial(r, j);
  const power = (base: string, k: number) => (k === 0 ? '' : k === 1 ? base : `${base}^{${k}}`);
  return `${c === 1 ? '' : c}${power('t', j)}${power('(1-t)', r - j)}`;
}

/** P_{r,first} in the control points: (1 − t)²P_0 + 2t(1 − t)P_1 + t²P_2. */
export function expansionTex(r: number, first = 0): string {
  if (r > WRITTEN_OUT) return `\\sum_{j=0}^{${r}} W(${r},j,t)\\,P_{${first}+j}`;
  return Array.from({ length: r + 1 }, (_, j) => `${weightTex(r, j)}\\,P_{${first + j}}`).join(
    ' + ',
  );
}

/** Terms with their numbers, w·P (all of them, or the ends around \dots). */
function numbersTex(m: DeCasteljauModel, r: number): string {
  const terms = m.weights[r].map((w, j) => `${texT(w)}\\cdot${exactPoint(m.state.p[j])}`);
  const shown = terms.length > 5 ? [terms[0], terms[1], '\\dots', terms[r]] : terms;
  return `${shown.join(' + ')} = ${exactPoint(m.blends[r][0])}`;
}

/**
 * Level r's first point expanded back into the control points, with the
 * numbers: the recursion (1 − t)P_{r−1,0} + tP_{r−1,1}, written out in braces
 * up to level 3 (the braces are the recursion, so it is not written twice),
 * the expansion, Σ W(n, i, t) Pᵢ at the last level (beside the expansion,
 * where one is written out), and the numbers. At most three lines to level
 * 3: five crowded the figure in presenter view (#19).
 */
function levelTex(m: DeCasteljauModel, r: number): string {
  if (r === 1) return `P_{1,i} = (1-t)\\,P_i + t\\,P_{i+1}:\\quad P_{1,0} = ${numbersTex(m, 1)}`;
  const lines =
    r <= 3
      ? [`P_{${r},0} &= (1-t)\\{${expansionTex(r - 1, 0)}\\} + t\\{${expansionTex(r - 1, 1)}\\}`]
      : [`P_{${r},0} &= (1-t)\\,P_{${r - 1},0} + t\\,P_{${r - 1},1}`];
  const sum = `\\textstyle\\sum_{i=0}^{${r}} W(${r},i,t)\\,P_i`;
  if (r <= WRITTEN_OUT) lines.push(`&= ${expansionTex(r)}${r === m.n ? ` = ${sum}` : ''}`);
  else if (r === m.n) lines.push(`&= ${sum}`);
  lines.push(`&= ${numbersTex(m, r)}`);
  return `\\begin{aligned}${lines.join('\\\\ ')}\\end{aligned}`;
}

/** The weights in words: 0.125, 0.375, 0.375, 0.125 (the ends around … when many). */
function weightWords(weights: readonly number[]): string {
  const all = weights.map(words);
  return (all.length > 5 ? [all[0], all[1], '…', all[all.length - 1]] : all).join(', ');
}

/**
 * The construction expanded back into the Bernstein form, level by level
 * (the lecture notes' "de Casteljau form" expands it backwards from P_{3,0};
 * the sums are the same): each level's points are blends of the control
 * points, and the last is Σ W(n, i, t) Pᵢ.
 */
export const bernsteinForm = script<DeCasteljauState, DeCasteljauModel, BernsteinReveal>(
  step(
    'points',
    ({ state }) =>
      `The ${degree(state) + 1} control points P₀ … P${sub(degree(state))}, and t = ${words(state.t)}`,
  ),
  repeat(
    'blend',
    degree,
    ({ state, model: m, index: r, times: n }) => {
      if (r === 1)
        return `Level 1 in the control points: each point is ${words(1 - state.t)} of Pᵢ and ${words(state.t)} of Pᵢ₊₁`;
      // The last level's formula is three tall lines, its weights in the last:
      // the words keep to one line (#19).
      if (r === n) return `Level ${r} expanded: P${sub(r)},₀ = Σ W(${n}, i, t) Pᵢ`;
      return `Level ${r} expanded: P${sub(r)},₀ blends P₀ … P${sub(r)}, with weights ${weightWords(m.weights[r])}`;
    },
    ({ model, index: r }) => levelTex(model, r),
  ),
  step(
    'same',
    ({ state, model: m }) =>
      `The construction's P${sub(m.n)},₀ is the same point: P(${words(state.t)}) on the curve`,
    ({ model: m }) =>
      `P_{${m.n},0} = ${exactPoint(m.levels[m.n][0])}\\ \\text{(construction)},\\quad \\sum_{i=0}^{${m.n}} W(${m.n},i,t)\\,P_i = ${exactPoint(m.blends[m.n][0])},\\quad \\text{apart by } ${texResidue(m.blendGap)}`,
  ),
);
