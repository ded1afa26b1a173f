import { texResidue } from '../../kit/format';
import { narrow, script, step } from '../../kit/script';
import type { ConvertModel, LocalModel, PropertiesModel } from './model';
import { blend, n3, pt } from './notation';
import type { BSplineState } from './state';

/** What the steps of local control reveal, by name. */
export type LocalReveal = 'points' | 'curves' | 'moved' | 'basis';

/** Local control: the B-spline against one Bézier curve of the same points, before and after. */
export const localScript = script<BSplineState, LocalModel, LocalReveal>(
  step('points', 'The control points'),
  step(
    'curves',
    'The B-spline (colours) and the single Bézier curve (grey) through the same points',
  ),
  step(
    'moved',
    'One point moved: only its four segments change; the Bézier curve moves along its whole length',
    ({ model: m }) => {
      const { moved, changed } = m.localControl;
      if (moved.length === 0) return '\\text{drag a control point}';
      const names = m.segments.flatMap((_, i) => (changed[i] ? [`Q_{${i + 3}}`] : []));
      return `\\text{moved } ${moved.map((j) => `P_{${j}}`).join(', ')}:\\ \\text{changed } ${names.join(', ')}\\ \\text{of } ${m.segments.length}`;
    },
  ),
  step(
    'basis',
    'The plot of the basis functions: each is non-zero on four segments only',
    ({ model: m }) => `P(s{=}${n3(m.u)}) = ${blend(m.basis, (j) => `P_{${j}}`)}`,
  ),
);

/** What the steps of the B-spline ↔ Bézier conversion reveal, by name. */
export type ConvertReveal = 'points' | 'curve' | 'bezier' | 'beziers' | 'back';

/** The four B-spline points of the segment under the cursor, as TeX names. */
const fourNames = (m: ConvertModel) => [0, 1, 2, 3].map((k) => `P_{${m.segment + k}}`);

/** The four Bézier points of the segment under the cursor from its four B-spline points, as `name &= rule = value`. */
function toBezier(m: ConvertModel): string[] {
  const [a, b, c, d] = fourNames(m);
  const bez = m.beziers[m.segment];
  return [
    `B_0 &= \\tfrac16(${a} + 4${b} + ${c}) = ${pt(bez[0])}`,
    `B_1 &= \\tfrac13(2${b} + ${c}) = ${pt(bez[1])}`,
    `B_2 &= \\tfrac13(${b} + 2${c}) = ${pt(bez[2])}`,
    `B_3 &= \\tfrac16(${b} + 4${c} + ${d}) = ${pt(bez[3])}`,
  ];
}

/** And back: the four B-spline points from the four Bézier points. */
function fromBezier(m: ConvertModel): string[] {
  const [a, b, c, d] = fourNames(m);
  const back = m.back;
  return [
    `${a} &= 6B_0 - 7B_1 + 2B_2 = ${pt(back[0])}`,
    `${b} &= 2B_1 - B_2 = ${pt(back[1])}`,
    `${c} &= 2B_2 - B_1 = ${pt(back[2])}`,
    `${d} &= 2B_1 - 7B_2 + 6B_3 = ${pt(back[3])}`,
  ];
}

/** Four equations two to a line, so the figure keeps its room on the projector. */
const twoByTwo = ([a, b, c, d]: string[]) =>
  `\\begin{aligned}${a} & ${b}\\\\ ${c} & ${d}\\end{aligned}`;

/** The four equations one under another, for a narrow box (a laptop's panel: 422 px two by two in 404). */
const oneAColumn = (rows: string[]) => `\\begin{aligned}${rows.join('\\\\ ')}\\end{aligned}`;

/** A step of four equations: two by two on the projector, one a line in the panel. */
const fourEquations = (
  name: ConvertReveal,
  caption: string,
  equations: (m: ConvertModel) => string[],
) =>
  narrow(
    step<BSplineState, ConvertModel, ConvertReveal>(name, caption, ({ model }) =>
      twoByTwo(equations(model)),
    ),
    ({ model }) => oneAColumn(equations(model)),
  );

/** B-spline ↔ Bézier, segment by segment. */
export const convertScript = script<BSplineState, ConvertModel, ConvertReveal>(
  step('points', 'The control points'),
  step('curve', 'The uniform cubic B-spline'),
  fourEquations(
    'bezier',
    'The segment under the cursor as a Bézier curve: its four Bézier points from its four B-spline points',
    toBezier,
  ),
  step('beziers', 'Every segment as a Bézier curve: neighbours share their end points'),
  fourEquations(
    'back',
    'And back: the four Bézier points give the four B-spline points again',
    fromBezier,
  ),
);

/** What the steps of the properties scene reveal, by name. */
export type PropertiesReveal = 'points' | 'curve' | 'hulls' | 'line' | 'affine';

/** Convex hulls, variation diminishing, affine invariance. */
export const propertiesScript = script<BSplineState, PropertiesModel, PropertiesReveal>(
  step('points', 'The control points'),
  step('curve', 'The uniform cubic B-spline'),
  step('hulls', 'Each segment lies in the convex hull of its four control points'),
  step(
    'line',
    'Variation diminishing: no line crosses the curve more often than the polygon',
    ({ model: m }) => {
      const { crossings } = m.properties;
      return `\\#(\\text{line} \\cap \\text{curve}) = ${crossings.curve} \\;\\le\\; \\#(\\text{line} \\cap \\text{polygon}) = ${crossings.polygon}`;
    },
  ),
  step(
    'affine',
    'Affine invariance: the curve of the mapped points is the mapped curve',
    ({ model: m }) =>
      `\\max\\,\\lvert A(P(s)) - P_{AP}(s) \\rvert = ${texResidue(m.properties.deviation)}`,
  ),
);
