import { smallNumber, sub, trimmed } from '../../kit/format';
import { narrow, repeat, script, step } from '../../kit/script';
import { controlPointName, type Point } from '../../math';
import { texPoint } from '../../render/formula';
import type { BezierSplinesModel } from './model';
import { pressItems, presses } from './presses';
import type { BezierSplinesState } from './state';
import type { InTermsOfB } from './workedExample';
import { type SplineKind, rowName } from './splineRows';

/** What the steps of the worked example reveal, by name. */
export type WorkedReveal =
  | 'points'
  | 'c1Count'
  | 'c1First'
  | 'c1Mirror'
  | 'c1Output'
  | 'c2Count'
  | 'c2Start'
  | 'c2Joint'
  | 'c2End'
  | 'c2Back'
  | 'c2Output';

type State = BezierSplinesState;
type Model = BezierSplinesModel;

const pt = (p: Point) => texPoint(p, 2);
const pieces = (s: State) => s.points.length - 1;
const aligned = (rows: string[]) => `\\begin{aligned}${rows.join('\\\\')}\\end{aligned}`;
/** Items three to a line, so the numbers stay large in presenter view. */
const lines = (items: string[], perLine = 3) =>
  Array.from({ length: Math.ceil(items.length / perLine) }, (_, r) =>
    items.slice(perLine * r, perLine * r + perLine).join(',\\quad '),
  ).map((line) => `&${line}`);
const threeALine = (items: string[]) => aligned(lines(items));

/** Control point j of the C² spline: the practical's A … J for four points, else c with its index. */
const name = (j: number, n: number) => {
  const text = controlPointName(j, 3 * n + 1);
  return text.startsWith('c_') ? `c${sub(j)}` : text;
};
const texName = (j: number, n: number) => controlPointName(j, 3 * n + 1);

/** a·B + v in TeX: (2.00,\ 5.00) - 2B, 2B, (4.00,\ 10.00). */
export function texInTermsOfB({ a, v }: InTermsOfB): string {
  const vector = Math.abs(v[0]) < 1e-12 && Math.abs(v[1]) < 1e-12 ? '' : pt(v);
  if (a === 0) return vector || pt(v);
  const size = Math.abs(a) === 1 ? 'B' : `${trimmed(Math.abs(a), 6)}B`;
  if (!vector) return a < 0 ? `-${size}` : size;
  return `${vector} ${a < 0 ? '-' : '+'} ${size}`;
}

/** The list p₀, b₀, p₁, …, pₙ in TeX, with a gap in the middle when it is long. */
const c1Names = (n: number) => {
  const all = Array.from({ length: 2 * n + 1 }, (_, j) =>
    j % 2 === 0 ? `p_{${j / 2}}` : `b_{${(j - 1) / 2}}`,
  );
  return all.length <= 9
    ? all.join(',\\ ')
    : `${all.slice(0, 4).join(',\\ ')},\\ \\dots,\\ ${all.slice(-2).join(',\\ ')}`;
};

/**
 * A row of a function's output: its number, as the checker below numbers
 * them, and its name as the figure labels that point (p₀, b₀, … for C¹; the
 * practical's letters A, B, … for C²).
 */
const row = (q: Point, j: number, kind: SplineKind, n: number) => {
  const name = rowName(j, kind, n);
  const tex =
    kind === 'C1'
      ? `${name[0]}_{${(j - (j % 2)) / 2}}`
      : name.length === 1
        ? `\\text{${name}}`
        : `c_{${j}}`;
  return `${j}\\ (${tex})\\!:\\ ${pt(q)}`;
};
/** computeSplineC2's output, each point with its number and name. */
const c2Rows = (model: Model, state: State) =>
  model.worked.c2.controls.map((q, j) => row(q, j, 'C2', pieces(state)));
const rows = (output: readonly Point[], n: number) =>
  lines(output.map((q, j) => row(q, j, 'C1', n)));

/** The inner joints a press of the C² walk covers. */
const jointsOf = (s: State, press: number) => pressItems(pieces(s) - 1, press);

/** Part 7: the practical's computeSplineC1 and computeSplineC2 through the same points, by hand. */
export const worked = script<State, Model, WorkedReveal>(
  step(
    'points',
    ({ state }) =>
      `The ${state.points.length} points p${sub(0)} … p${sub(pieces(state))} that computeSplineC1 and computeSplineC2 both get`,
    ({ state }) => threeALine(state.points.map((q, i) => `p_{${i}} = ${pt(q)}`)),
  ),
  step(
    'c1Count',
    ({ state }) => {
      const n = pieces(state);
      return `computeSplineC1: n = ${n} quadratic pieces [pᵢ, bᵢ, pᵢ₊₁], so 2n + 1 = ${2 * n + 1} control points, of which the ${n} bᵢ are unknown`;
    },
    ({ state }) => {
      const n = pieces(state);
      return `2n + 1 = 2\\cdot ${n} + 1 = ${2 * n + 1}:\\quad ${c1Names(n)}`;
    },
  ),
  step(
    'c1First',
    `b${sub(0)} is free: the midpoint of p${sub(0)}p${sub(1)}, as the practical suggests, gives the first piece`,
    ({ state: { points: p }, model }) =>
      `b_0 = \\tfrac{1}{2}(p_0 + p_1) = \\tfrac{1}{2}\\big(${pt(p[0])} + ${pt(p[1])}\\big) = ${pt(model.worked.c1.b[0])}`,
  ),
  // One press per further piece (several per press for many points): b₁ … bₙ₋₁.
  repeat(
    'c1Mirror',
    (s) => presses(pieces(s) - 1),
    ({ state, index }) => {
      const items = pressItems(pieces(state) - 1, index);
      const [i] = items;
      if (items.length === 1)
        return `C¹ at p${sub(i)}: b${sub(i)} = 2p${sub(i)} − b${sub(i - 1)}, the mirror image of b${sub(i - 1)} through p${sub(i)}`;
      const last = items[items.length - 1];
      return `C¹ at p${sub(i)} … p${sub(last)}: each bᵢ = 2pᵢ − bᵢ₋₁, the mirror image of the one before`;
    },
    ({ state, model, index }) => {
      const b = model.worked.c1.b;
      return aligned(
        pressItems(pieces(state) - 1, index).map(
          (i) =>
            `b_{${i}} &= 2p_{${i}} - b_{${i - 1}} = 2${pt(state.points[i])} - ${pt(b[i - 1])} = ${pt(b[i])}`,
        ),
      );
    },
  ),
  step(
    'c1Output',
    ({ state }) =>
      `computeSplineC1 returns the ${2 * pieces(state) + 1} control points in this order, numbered from row 0`,
    ({ model, state }) => aligned(rows(model.worked.c1.output, pieces(state))),
  ),
  step(
    'c2Count',
    ({ state }) => {
      const n = pieces(state);
      const size = 3 * n + 1;
      const all = `${name(0, n)} … ${name(3 * n, n)}`;
      const given = state.points.map((_, i) => name(3 * i, n)).join(', ');
      return n === 3
        ? `computeSplineC2: ${n} cubic pieces, ${size} control points ${all}; ${given} are the points, the ${2 * n} others unknown`
        : `computeSplineC2: ${n} cubic pieces, ${size} control points ${all}; every third is a point, the ${2 * n} others unknown`;
    },
    ({ state }) => {
      const n = pieces(state);
      return `3n + 1 = ${3 * n + 1} = \\underbrace{${n + 1}}_{\\text{points}} + \\underbrace{${n - 1}}_{\\text{C¹}} + \\underbrace{${n - 1}}_{\\text{C²}} + \\underbrace{2}_{\\text{natural ends}}`;
    },
  ),
  step(
    'c2Start',
    ({ state }) => {
      const n = pieces(state);
      const [a, b, c] = [name(0, n), name(1, n), name(2, n)];
      const unknown = b === 'B' ? 'B' : `${b} (call it B)`;
      return `Keep ${unknown} unknown: the natural start ${a} − 2${b} + ${c} = 0 gives ${c} = 2B − ${a}`;
    },
    ({ state, model }) => {
      const n = pieces(state);
      return `${texName(2, n)} = 2B - ${texName(0, n)} = ${texInTermsOfB(model.worked.c2.forms[2])}`;
    },
  ),
  // One press per inner joint (several per press for many points): its C¹ and C² equations.
  repeat(
    'c2Joint',
    (s) => presses(pieces(s) - 1),
    ({ state, index }) => {
      const n = pieces(state);
      const joints = jointsOf(state, index);
      if (joints.length > 1)
        return `At ${name(3 * joints[0], n)} … ${name(3 * joints[joints.length - 1], n)}: C¹ and C² give the next two control points at each joint`;
      const k = 3 * joints[0];
      const c = (j: number) => name(j, n);
      return `At ${c(k)}: C¹ gives ${c(k + 1)} = 2${c(k)} − ${c(k - 1)}, C² gives ${c(k + 2)} = ${c(k - 2)} − 2${c(k - 1)} + 2${c(k + 1)}`;
    },
    ({ state, model, index }) => {
      const n = pieces(state);
      const c = (j: number) => texName(j, n);
      const { forms } = model.worked.c2;
      return aligned(
        jointsOf(state, index).flatMap((i) => {
          const k = 3 * i;
          return [
            `${c(k + 1)} &= 2${c(k)} - ${c(k - 1)} = ${texInTermsOfB(forms[k + 1])}`,
            `${c(k + 2)} &= ${c(k - 2)} - 2${c(k - 1)} + 2${c(k + 1)} = ${texInTermsOfB(forms[k + 2])}`,
          ];
        }),
      );
    },
  ),
  step(
    'c2End',
    ({ state }) => {
      const n = pieces(state);
      const c = (j: number) => name(j, n);
      return `The natural end ${c(3 * n - 2)} − 2${c(3 * n - 1)} + ${c(3 * n)} = 0, the one equation left, fixes B`;
    },
    ({ state, model }) => {
      const n = pieces(state);
      const c = (j: number) => texName(j, n);
      const { end, B } = model.worked.c2;
      const divide =
        end.a < 0 ? `\\tfrac{1}{${trimmed(-end.a, 6)}}` : `-\\tfrac{1}{${trimmed(end.a, 6)}}`;
      return `${c(3 * n - 2)} - 2${c(3 * n - 1)} + ${c(3 * n)} = ${texInTermsOfB(end)} = 0 \\;\\Rightarrow\\; B = ${divide}${pt(end.v)} = ${pt(B)}`;
    },
  ),
  step('c2Back', 'Put B back in: every other unknown control point follows', ({ state, model }) => {
    const n = pieces(state);
    const { controls } = model.worked.c2;
    return threeALine(
      controls.flatMap((q, j) => (j % 3 === 0 || j === 1 ? [] : [`${texName(j, n)} = ${pt(q)}`])),
    );
  }),
  narrow(
    step(
      'c2Output',
      ({ state, model }) => {
        // How far the hand's numbers are from the whole system solved at once (the maths' solver).
        const off = model.worked.c2.solverDifference;
        const agree =
          off < 1e-12 ? 'they agree to 12 digits' : `they differ by ${smallNumber(off)}`;
        return `computeSplineC2 returns the ${3 * pieces(state) + 1} control points in order: the C² spline, as the whole system solved at once (${agree})`;
      },
      // Five to a line: the figure keeps its room on the projector.
      ({ model, state }) => aligned(lines(c2Rows(model, state), 5)),
    ),
    // Two to a line in a narrow box (a laptop's panel: five ran 592 px in 404).
    ({ model, state }) => aligned(lines(c2Rows(model, state), 2)),
  ),
);
