import type { StepsSpec } from '../../app/lesson';
import { texNumber, texPoint } from '../../render/formula';
import type { BSplineModel } from './model';
import { type BSplineState, type Part, isUniformPart } from './state';

const n3 = (v: number) => texNumber(v, 3);
const SUPERSCRIPTS = '⁰¹²³⁴⁵⁶⁷⁸⁹';
/** A small whole number as Unicode superscript digits (C², C⁰), for captions and labels. */
export const superscript = (n: number) =>
  [...String(n)].map((c) => (c === '-' ? '⁻' : SUPERSCRIPTS[Number(c)])).join('');
const pt = (p: readonly number[]) => texPoint(p, 2);
/** The lecture names a segment after its last control point: Q_i blends x_{i−3} … x_i. */
export const segmentName = (first: number) => `Q${first + 3}`;

/** How many segments the uniform cubic has: m − 2 open, m + 1 closed. */
export const uniformSegments = (s: BSplineState) =>
  s.x === 'closed' ? s.p.length : s.p.length - 3;

const FIXED: Partial<Record<Part, number>> = {
  uniform: 4,
  closed: 4,
  local: 3,
  convert: 4,
  properties: 4,
  nurbs: 3,
  circle: 4,
  projective: 3,
};

export const stepCount = (s: BSplineState) => FIXED[s.x] ?? s.d + 3;

/** The segment under the cursor of the uniform cubic (0-based). */
const segmentAt = (s: BSplineState) => {
  const count = uniformSegments(s);
  return Math.min(Math.floor(s.t * count), count - 1);
};

function describeUniform(s: BSplineState, k: number): string {
  const m = s.p.length - 1;
  const closed = s.x === 'closed';
  const count = uniformSegments(s);
  const i = segmentAt(s);
  const blends = [0, 1, 2, 3].map((j) => `x${(i + j) % s.p.length}`).join(', ');
  switch (k) {
    case 0:
      return `The m + 1 = ${m + 1} control points x0 … x${m}`;
    case 1:
      return closed
        ? `The closed control polygon: x${m} joins x0 again`
        : 'The control polygon: the curve will follow it, but pass through none of its points';
    case 2:
      return `Segment ${segmentName(i)} blends ${blends} with the 1/6 matrix`;
    case 3:
      return closed
        ? `All m + 1 = ${count} segments, one colour each, with the same matrix everywhere: a closed C² curve`
        : `All m − 2 = ${count} segments, one colour each: they join with C² continuity`;
    default:
      return 'Each joint is (x(i−1) + 4x(i) + x(i+1))/6; P(t) runs along the whole curve';
  }
}

const DESCRIBE: Partial<Record<Part, readonly string[]>> = {
  local: [
    'The control points',
    'The B-spline (colours) and the single Bézier curve (grey) through the same points',
    'One point moved: only its four segments change; the Bézier curve moves along its whole length',
    'The basis functions below: each is non-zero on four segments only',
  ],
  convert: [
    'The control points',
    'The uniform cubic B-spline',
    'The segment under the cursor as a Bézier curve: G_Bez = M_Bez⁻¹ · M_B · G_B',
    'Every segment as a Bézier curve: neighbours share their end points',
    'And back: M_B⁻¹ · M_Bez · G_Bez gives the four B-spline points again',
  ],
  properties: [
    'The control points',
    'The uniform cubic B-spline',
    'Each segment lies in the convex hull of its four control points',
    'Variation diminishing: no line crosses the curve more often than the polygon',
    'Affine invariance: the curve of the mapped points is the mapped curve',
  ],
  nurbs: [
    'The control points',
    'All weights 1: the plain B-spline',
    'Weights: a heavier point pulls the curve towards itself, a lighter one lets it go',
    'C(u) = Σ wᵢNᵢ(u)xᵢ / Σ wᵢNᵢ(u), with the numbers at u',
  ],
  circle: [
    'Nine control points on a square',
    'The polygon; weight 1 at the edge midpoints, √2/2 at the corners',
    'Four rational quadratic arcs, one per quarter',
    'Sampled points of the curve lie on the circle, to rounding',
    'With every weight 1 instead: not a circle',
  ],
  projective: [
    'The control points',
    'The NURBS curve',
    'A perspective map of the control points, each weight times its new w: the image of the curve',
    'The same mapped points with their old weights: a different curve',
  ],
};

function describeKnots(s: BSplineState, k: number): string {
  const n = s.p.length;
  const p = s.d;
  if (k === 0) return `The n = ${n} control points x0 … x${n - 1}`;
  if (k === 1) return `The knot vector u0 … u${n + p}: n + p + 1 = ${n + p + 1} knots on the strip`;
  if (k <= p + 2) {
    const r = k - 2;
    return r === 0
      ? 'Row 0 of Cox–de Boor: N(i,0) = 1 on [u(i), u(i+1)), else 0'
      : `Row ${r}: each N(i,${r}) blends N(i,${r - 1}) and N(i+1,${r - 1})`;
  }
  return s.x === 'clamped'
    ? `The curve of degree ${p}: with p + 1 = ${p + 1} equal end knots it starts at x0 and ends at x${n - 1}`
    : `The curve of degree ${p}: at a knot of multiplicity k it is C${superscript(p)}⁻ᵏ`;
}

export const describeStep = (s: BSplineState, k: number): string => {
  if (s.x === 'uniform' || s.x === 'closed') return describeUniform(s, k);
  const fixed = DESCRIBE[s.x];
  return fixed ? fixed[Math.min(k, fixed.length - 1)] : describeKnots(s, k);
};

/** Σ (number) x_i over the non-zero terms, e.g. `0.167\,x_{2} + 0.667\,x_{3}`. */
function blend(values: readonly number[], names: (i: number) => string): string {
  return values
    .map((v, i) => (v === 0 ? '' : `${n3(v)}\\,${names(i)}`))
    .filter(Boolean)
    .join(' + ');
}

function uniformFormula(m: BSplineModel, s: BSplineState): string | null {
  const i = m.segment;
  const names = (j: number) => `x_{${m.owner[j]}}`;
  const t = n3(m.local);
  if (s.k === 2) {
    return `${segmentName(i).replace(/(\d+)/, '_{$1}')}(${t}) = ${blend(m.basis, names)} = ${pt(m.point)}`;
  }
  if (s.k === 3) {
    const points = s.p.length;
    return s.x === 'closed'
      ? `m + 1 = ${points}\\text{ points} \\;\\to\\; m + 1 = ${points}\\text{ segments}`
      : `m + 1 = ${points}\\text{ points} \\;\\to\\; m - 2 = ${points - 3}\\text{ segments}`;
  }
  if (s.k >= 4) {
    const joint = m.segments[i].bezier![0];
    const [a, b, c] = [0, 1, 2].map((k) => `x_{${m.owner[i + k]}}`);
    return `${segmentName(i).replace(/(\d+)/, '_{$1}')}(0) = \\tfrac16(${a} + 4${b} + ${c}) = ${pt(joint)}`;
  }
  return null;
}

function localFormula(m: BSplineModel, s: BSplineState): string | null {
  const local = m.localControl!;
  if (s.k === 2) {
    if (local.moved.length === 0) return '\\text{drag a control point}';
    const changed = m.segments.flatMap((_, i) => (local.changed[i] ? [`Q_{${i + 3}}`] : []));
    return `\\text{moved } ${local.moved.map((j) => `x_{${j}}`).join(', ')}:\\ \\text{changed } ${changed.join(', ')}\\ \\text{of } ${m.segments.length}`;
  }
  if (s.k >= 3) return `P(s{=}${n3(m.u)}) = ${blend(m.basis, (j) => `x_{${j}}`)}`;
  return null;
}

function convertFormula(m: BSplineModel, s: BSplineState): string | null {
  const i = m.segment;
  const [a, b, c, d] = [0, 1, 2, 3].map((k) => `x_{${i + k}}`);
  const bez = m.segments[i].bezier!;
  if (s.k === 2) {
    return `\\begin{aligned}B_0 &= \\tfrac16(${a} + 4${b} + ${c}) = ${pt(bez[0])} & B_1 &= \\tfrac13(2${b} + ${c}) = ${pt(bez[1])}\\\\ B_2 &= \\tfrac13(${b} + 2${c}) = ${pt(bez[2])} & B_3 &= \\tfrac16(${b} + 4${c} + ${d}) = ${pt(bez[3])}\\end{aligned}`;
  }
  if (s.k >= 4) {
    const back = m.convert!.bspline;
    return `\\begin{aligned}${a} &= 6B_0 - 7B_1 + 2B_2 = ${pt(back[0])} & ${b} &= 2B_1 - B_2 = ${pt(back[1])}\\\\ ${c} &= 2B_2 - B_1 = ${pt(back[2])} & ${d} &= 2B_1 - 7B_2 + 6B_3 = ${pt(back[3])}\\end{aligned}`;
  }
  return null;
}

function propertiesFormula(m: BSplineModel, s: BSplineState): string | null {
  const props = m.properties!;
  if (s.k === 3) {
    return `\\#(\\text{line} \\cap \\text{curve}) = ${props.crossings.curve} \\;\\le\\; \\#(\\text{line} \\cap \\text{polygon}) = ${props.crossings.polygon}`;
  }
  if (s.k >= 4) {
    return `\\max\\,\\lvert A(P(s)) - P_{A x}(s) \\rvert = ${props.deviation.toExponential(1)}`;
  }
  return null;
}

/** The Cox–de Boor triangle up to row r at u: the non-zero columns i = span − p … span. */
export function triangleTex(m: BSplineModel, r: number): string {
  const p = m.degree;
  const span = m.table[0].indexOf(1);
  const columns = Array.from({ length: p + 1 }, (_, k) => span - p + k);
  const head = columns.map((i) => `i = ${i}`).join(' & ');
  const rows = m.table
    .slice(0, r + 1)
    .map(
      (row, q) =>
        `N_{i,${q}} & ${columns.map((i) => (i >= 0 && i < row.length ? n3(row[i]) : '')).join(' & ')}`,
    );
  return `u = ${n3(m.u)}:\\quad\\begin{array}{r|${'c'.repeat(p + 1)}} & ${head} \\\\ \\hline ${rows.join(' \\\\ ')}\\end{array}`;
}

function knotsFormula(m: BSplineModel, s: BSplineState): string | null {
  const p = m.degree;
  if (s.k === 1) return `u = (${m.knots.map((v) => texNumber(v, 2)).join(',\\ ')})`;
  if (s.k >= 2 && s.k <= p + 2) {
    const r = s.k - 2;
    const sum =
      r === p
        ? `\\quad \\textstyle\\sum_i N_{i,${p}} = ${n3(m.basis.reduce((a, b) => a + b, 0))}`
        : '';
    return triangleTex(m, r) + sum;
  }
  if (s.k > p + 2) {
    return `C(${n3(m.u)}) = ${blend(m.basis, (i) => `x_{${i}}`)} = ${pt(m.point)}`;
  }
  return null;
}

function rationalFormula(m: BSplineModel, s: BSplineState): string | null {
  if (s.x === 'nurbs' && s.k >= 3) {
    const terms = m.basis.flatMap((b, i) =>
      b === 0 ? [] : [`${texNumber(m.weights[i], 2)}\\cdot${n3(b)}\\,x_{${i}}`],
    );
    return `C(${n3(m.u)}) = \\dfrac{${terms.join(' + ')}}{${n3(m.rational!.denominator)}} = ${pt(m.point)}`;
  }
  if (s.x === 'circle' && m.circle) {
    if (s.k === 3)
      return `\\max_u \\bigl\\lvert\\, \\lVert C(u) - c \\rVert - r \\,\\bigr\\rvert = ${m.circle.deviation.toExponential(1)}`;
    if (s.k >= 4)
      return `\\text{all } w_i = 1:\\ \\max_u \\bigl\\lvert\\, \\lVert C(u) - c \\rVert - r \\,\\bigr\\rvert = ${n3(m.circle.plainDeviation)}`;
  }
  if (s.x === 'projective' && m.projective && !m.projective.error) {
    const pr = m.projective;
    if (s.k === 2)
      return `w'_i = w_i\\,(h_{20}x_i + h_{21}y_i + h_{22}):\\ \\max_u \\lvert C_{Hx,\\,w'}(u) - H(C(u)) \\rvert = ${pr.deviation.toExponential(1)}`;
    if (s.k >= 3)
      return `\\text{old weights: } \\max_u \\lvert C_{Hx,\\,w}(u) - H(C(u)) \\rvert = ${n3(pr.plainDeviation)}`;
  }
  return null;
}

export const steps: StepsSpec<BSplineState, BSplineModel> = {
  key: 'k',
  count: stepCount,
  describe: describeStep,
  formula(m, s) {
    switch (s.x) {
      case 'uniform':
      case 'closed':
        return uniformFormula(m, s);
      case 'local':
        return localFormula(m, s);
      case 'convert':
        return convertFormula(m, s);
      case 'properties':
        return propertiesFormula(m, s);
      case 'knots':
      case 'clamped':
      case 'repeated':
        return knotsFormula(m, s);
      default:
        return isUniformPart(s.x) ? null : rationalFormula(m, s);
    }
  },
};
