import type { Point } from '../../math';
import { texNumber } from '../../render/formula';
import type { DeCasteljauModel } from './model';
import { type DeCasteljauState, degree, lastStep, stage } from './state';

const SUBSCRIPTS = '₀₁₂₃₄₅₆₇₈₉';
/** 12 → "₁₂": an index as Unicode subscripts, for captions that are plain text. */
export const sub = (i: number) => [...String(i)].map((d) => SUBSCRIPTS[Number(d)]).join('');

/** A number in a caption: up to three decimals, trailing zeros dropped, a true minus sign. */
export const words = (v: number) => {
  const text = String(Number(v.toFixed(3)));
  return text === '-0' ? '0' : text.replace('-', '−');
};

/** t as typed: up to four decimals, trailing zeros dropped. */
export const texT = (t: number) => String(Number(t.toFixed(4)));
const texPoint = (p: readonly number[]) => `(${p.map((v) => texNumber(v, 3)).join(',\\ ')})`;

/** The caption of step k: the control points, the polygon, each level, the curve traced. */
export function describeStep(state: DeCasteljauState, k: number): string {
  const n = degree(state);
  const t = words(state.t);
  if (k <= 0) return `The ${n + 1} control points P₀ … P${sub(n)}, and nothing else yet`;
  if (k === 1) return 'Join them in order: the control polygon, level 0';
  if (k >= lastStep(state)) return 'As t runs from 0 to 1, the point P(t) traces the Bézier curve';
  const r = k - 1;
  if (r === n) return `Level ${n}: one point is left, the point P(t) on the curve at t = ${t}`;
  const count = n - r + 1;
  return `Level ${r}: every edge of level ${r - 1} cut at t = ${t}, ${count} new point${count === 1 ? '' : 's'}`;
}

/** The formula of the current step, with its numbers. */
export function stepFormula(m: DeCasteljauModel, state: DeCasteljauState): string | null {
  const { n, levels } = m;
  const t = texT(state.t);
  const k = state.step;
  const shown = stage(state);
  if (k === 0) {
    if (n > 4)
      return `P_0 = ${texPoint(state.p[0])},\\ \\dots,\\ P_{${n}} = ${texPoint(state.p[n])}`;
    return state.p.map((q: Point, i) => `P_{${i}} = ${texPoint(q)}`).join(',\\ ');
  }
  if (k === 1) return `P_{0,i} = P_i,\\quad i = 0,\\dots,${n}`;
  if (shown.curve) {
    return `P(${t}) = \\sum_{i=0}^{${n}} W(${n},i,${t})\\,P_i = ${texPoint(m.bernsteinPoint)}`;
  }
  const r = shown.levels;
  const name = r === n ? `P(${t}) = P_{${r},0}` : `P_{${r},0}`;
  return `${name} = ${texT(1 - state.t)}\\cdot${texPoint(levels[r - 1][0])} + ${t}\\cdot${texPoint(levels[r - 1][1])} = ${texPoint(levels[r][0])}`;
}
