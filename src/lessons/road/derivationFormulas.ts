import { texNumber, trimmed } from '../../kit/format';
import { type FormulaParts, joined, live, tex } from '../../render/formulaParts';
import type { CoordinateWork, Derivation } from './derivation';

// The formula of each step of the derivation, for one coordinate (the
// slides write y; x is worked out the same way), with the current numbers.

/** The steps of the derivation that have a formula of their own (see derivationScript.ts). */
export type DerivationStep =
  | 'villages'
  | 'pieces'
  | 'parameter'
  | 'left'
  | 'right'
  | 'second'
  | 'equal'
  | 'substitute'
  | 'row'
  | 'start'
  | 'end'
  | 'system';

/** Up to this many rows the system is written out in full; beyond, its first and last rows. */
const FULL_ROWS = 8;

/** Whole numbers as they are (the matrix's 1, 2, 4; 3(y₁ − y₀) = 48), others to four decimals. */
const shown = (value: number) => (Number.isInteger(value) ? String(value) : texNumber(value, 4));
const number = (value: number) => live(shown(value));
/** A number in a sum: negatives in brackets (part of the shape), by the text shown (−0.0000 is 0). */
const term = (value: number) =>
  shown(value).startsWith('-') ? tex`(${number(value)})` : number(value);
/** A village's coordinate, kept to 0.01: as typed (16, 20.5), negatives in brackets. */
const place = (value: number) => {
  const text = trimmed(value, 2);
  return text.startsWith('-') ? tex`(${live(text)})` : live(text);
};

/** Where the marker is: its segment i and local parameter p (p̄ᵢ = i). */
export interface Marker {
  pBar: number;
  piece: number;
  p: number;
}

/**
 * The formula of `step` for coordinate k (0: x, 1: y), with its numbers;
 * null where the step has none (a join step with no inner village). In the
 * panel (`flowing`) the system is one line its box breaks where it must.
 */
export function derivationFormula(
  step: DerivationStep,
  work: Derivation,
  k: 0 | 1,
  marker: Marker,
  flowing = false,
): FormulaParts | null {
  const c = work.coordinates[k];
  const v = k === 0 ? 'x' : 'y';
  const j = work.join;
  const m = work.m;
  switch (step) {
    case 'villages':
      return tex`${v}_0, \dots, ${v}_{${m}} = ${listed(c.values.map(place))}`;
    case 'pieces':
      return tex`${v}_i(p) = a_i + b_i\,p + c_i\,p^2 + d_i\,p^3,\quad 0 \le p \le 1,\quad i = 0, \dots, ${m - 1}`;
    case 'parameter': {
      const { pBar, piece, p } = marker;
      return tex`p = \frac{\bar p - \bar p_{${piece}}}{\bar p_{${piece + 1}} - \bar p_{${piece}}} = \frac{${live(texNumber(pBar, 2))} - ${piece}}{${piece + 1} - ${piece}} = ${live(texNumber(p, 2))}`;
    }
    case 'left':
      return j === null ? null : pieceFormula(c, v, j - 1);
    case 'right':
      return j === null ? null : pieceFormula(c, v, j);
    case 'second': {
      if (j === null) return null;
      const i = j - 1;
      const [, , ci, di] = c.pieces[i];
      return tex`${v}''_{${i}}(p) = 2c_{${i}} + 6d_{${i}}\,p:\quad ${v}''_{${i}}(1) = 2c_{${i}} + 6d_{${i}} = 2${bracket(ci)} + 6${bracket(di)} = ${number(c.curvature[i][1])}`;
    }
    case 'equal': {
      if (j === null) return null;
      const i = j - 1;
      return tex`${v}''_{${i}}(1) = ${v}''_{${j}}(0):\quad 2c_{${i}} + 6d_{${i}} = 2c_{${j}}:\quad ${number(c.curvature[i][1])} = 2${bracket(c.pieces[j][2])} = ${number(c.curvature[j][0])}`;
    }
    case 'substitute':
      return j === null ? null : substituted(c, v, j);
    case 'row': {
      if (j === null) return null;
      const D = c.gradients;
      const left = D[j - 1] + 4 * D[j] + D[j + 1];
      return tex`D_{${j - 1}} + 4D_{${j}} + D_{${j + 1}} = 3(${v}_{${j + 1}} - ${v}_{${j - 1}}):\quad ${number(D[j - 1])} + 4${bracket(D[j])} + ${term(D[j + 1])} = ${live(trimmed(left, 4))} = 3(${place(c.values[j + 1])} - ${place(c.values[j - 1])})`;
    }
    case 'start': {
      const D = c.gradients;
      const left = 2 * D[0] + D[1];
      return tex`${v}''_0(0) = 2c_0 = 0 \;\Rightarrow\; 2D_0 + D_1 = 3(${v}_1 - ${v}_0):\quad 2${bracket(D[0])} + ${term(D[1])} = ${live(trimmed(left, 4))} = 3(${place(c.values[1])} - ${place(c.values[0])})`;
    }
    case 'end': {
      const D = c.gradients;
      const i = m - 1;
      const left = D[i] + 2 * D[m];
      return tex`${v}''_{${i}}(1) = 2c_{${i}} + 6d_{${i}} = 0 \;\Rightarrow\; D_{${i}} + 2D_{${m}} = 3(${v}_{${m}} - ${v}_{${i}}):\quad ${number(D[i])} + 2${bracket(D[m])} = ${live(trimmed(left, 4))} = 3(${place(c.values[m])} - ${place(c.values[i])})`;
    }
    case 'system':
      return systemFormula(c, m, flowing);
  }
}

/** A factor after a number: always in brackets, 2(−24.9761), 4(8.2775). */
const bracket = (value: number) => tex`(${number(value)})`;

/** Values separated by commas, the middle ones left out when there are many. */
function listed(values: readonly FormulaParts[], comma = ',\\ '): FormulaParts {
  if (values.length <= FULL_ROWS) return joined(values, comma);
  return joined([...values.slice(0, 3), tex`\dots`, ...values.slice(-2)], comma);
}

/**
 * a … d of segment i from the heights and gradients at its two ends: a and b
 * share a line, so the caption's three lines leave the map its room (#19).
 */
function pieceFormula(c: CoordinateWork, v: string, i: number): FormulaParts {
  const [a, b, cc, d] = c.pieces[i];
  const [y0, y1] = [place(c.values[i]), place(c.values[i + 1])];
  const [D0, D1] = [c.gradients[i], c.gradients[i + 1]];
  const lines = [
    tex`a_{${i}} &= ${v}_{${i}} = ${number(a)},\quad b_{${i}} = D_{${i}} = ${number(b)}`,
    tex`c_{${i}} &= 3(${v}_{${i + 1}} - ${v}_{${i}}) - 2D_{${i}} - D_{${i + 1}} = 3(${y1} - ${y0}) - 2${bracket(D0)} - ${term(D1)} = ${number(cc)}`,
    tex`d_{${i}} &= -2(${v}_{${i + 1}} - ${v}_{${i}}) + D_{${i}} + D_{${i + 1}} = -2(${y1} - ${y0}) + ${term(D0)} + ${term(D1)} = ${number(d)}`,
  ];
  return tex`\begin{aligned}${joined(lines, '\\\\ ')}\end{aligned}`;
}

/**
 * 2c(j−1) + 6d(j−1) = 2cj with c and d written in y and D, in symbols; then
 * each side in numbers, on a line of its own with its value (the two sides
 * in numbers on one line were too wide for the room's screen at 28 px).
 */
function substituted(c: CoordinateWork, v: string, j: number): FormulaParts {
  const i = j - 1;
  const y = (n: number) => place(c.values[n]);
  const D = c.gradients;
  const symbols = tex`&2[3(${v}_{${j}} - ${v}_{${i}}) - 2D_{${i}} - D_{${j}}] + 6[-2(${v}_{${j}} - ${v}_{${i}}) + D_{${i}} + D_{${j}}] = 2[3(${v}_{${j + 1}} - ${v}_{${j}}) - 2D_{${j}} - D_{${j + 1}}]`;
  const left = tex`&2[3(${y(j)} - ${y(i)}) - 2${bracket(D[i])} - ${term(D[j])}] + 6[-2(${y(j)} - ${y(i)}) + ${term(D[i])} + ${term(D[j])}] = ${number(c.curvature[i][1])}`;
  const right = tex`&2[3(${y(j + 1)} - ${y(j)}) - 2${bracket(D[j])} - ${term(D[j + 1])}] = ${number(c.curvature[j][0])}`;
  return tex`\begin{aligned}${symbols}\\ ${left}\\ ${right}\end{aligned}`;
}

/**
 * The whole system with its numbers, in two lines so the map keeps its room
 * on the projector: the end rows and the inner rows' right-hand sides, then
 * the D's it gives. Flowing, the same rows in one line broken after a comma
 * or an = where the box needs (a laptop's panel: 473–498 px in 404).
 */
function systemFormula(c: CoordinateWork, m: number, flowing: boolean): FormulaParts {
  const rhs = (i: number) => number(c.rhs[i]);
  // Flowing, a line may break after any comma of a list, as well as after an =.
  const comma = flowing ? ',\\allowbreak\\ ' : ',\\ ';
  const gap = flowing ? tex`,\allowbreak\quad ` : tex`,\quad `;
  const inner = Array.from({ length: m - 1 }, (_, k) => k + 1);
  const innerRows =
    inner.length === 0
      ? tex``
      : tex`${gap}D_{i-1} + 4D_{i} + D_{i+1} = ${listed(inner.map(rhs), comma)}\ (i = 1, \dots, ${m - 1})`;
  const solved = listed(
    c.gradients.map((d) => number(d)),
    comma,
  );
  if (flowing)
    return tex`2D_{0} + D_{1} = ${rhs(0)}${innerRows}${gap}D_{${m - 1}} + 2D_{${m}} = ${rhs(m)}\ \Rightarrow\ (D_{0}, \dots, D_{${m}}) = (${solved})`;
  return tex`\begin{aligned}&2D_{0} + D_{1} = ${rhs(0)}${innerRows},\quad D_{${m - 1}} + 2D_{${m}} = ${rhs(m)}\\ &\Rightarrow\ (D_{0}, \dots, D_{${m}}) = (${solved})\end{aligned}`;
}
