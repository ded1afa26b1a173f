import { sub, words } from '../../kit/format';
import { narrow, script, step } from '../../kit/script';
import type { ContinuityCase, JoinCheck } from './continuityGeometry';
import type { ContinuityModel } from './model';
import { pt, superscript } from './notation';
import type { BSplineState } from './state';

/** What the steps of degree p ⇒ Cᵖ⁻¹ reveal: the points, then one curve per press. */
export type ContinuityReveal = 'points' | ContinuityCase;

const PRIMES = ['', '′', '″', '‴'];

/** The r-th derivative's name in a caption or label: P, P′, P″, P‴, P⁽⁴⁾. */
export const derivativeName = (r: number) =>
  r < PRIMES.length ? `P${PRIMES[r]}` : `P⁽${superscript(r)}⁾`;
/** The same in TeX. */
const derivativeTex = (r: number) => (r < PRIMES.length ? `P${"'".repeat(r)}` : `P^{(${r})}`);

/** C², C⁰, C∞ for a caption or label. */
export const smoothName = (k: number) =>
  k === Infinity ? 'C∞' : k < 0 ? 'no C⁰ (a jump)' : `C${superscript(k)}`;

/** “P, P′ and P″ match left and right, P‴ does not”, from the check's numbers. */
function agreement(check: JoinCheck): string {
  if (check.smooth < 0) return 'P itself does not match left and right';
  const matching = Array.from(
    { length: Math.min(check.smooth, check.agree.length - 1) + 1 },
    (_, r) => derivativeName(r),
  );
  const list =
    matching.length === 1
      ? `${matching[0]} matches`
      : `${matching.slice(0, -1).join(', ')} and ${matching[matching.length - 1]} match`;
  const next = check.smooth + 1;
  return next < check.agree.length
    ? `${list} left and right, ${derivativeName(next)} does not`
    : `${list} left and right: one polynomial on both sides`;
}

/** What the knot's multiplicity promises, said as the rule: C² = C³⁻¹. */
function verdict(m: ContinuityModel): string {
  const { smooth, promised, multiplicity } = m.watched;
  const rule = `C${superscript(m.degree)}⁻${superscript(multiplicity)}`;
  return smooth === promised
    ? `${smoothName(smooth)} = ${rule}`
    : `${smoothName(smooth)}, more than the ${smoothName(promised)} = ${rule} promised, as these points lie`;
}

/** What the step did to the knots, in words. */
function knotsSaid(m: ContinuityModel): string {
  const c = m.watched.u;
  const u = (j: number) => `u${sub(j)}`;
  switch (m.knotCase) {
    case 'double':
      return `A double knot at u = ${words(c)} (${u(c + 1)} moved onto ${u(c)})`;
    case 'triple':
      return `A triple knot at u = ${words(c)} (${u(c - 1)} and ${u(c + 1)} moved onto ${u(c)})`;
    default:
      return `Degree ${m.degree} on simple knots, at u = ${words(c)}`;
  }
}

function caseCaption(m: ContinuityModel): string {
  const through = m.watched.through === null ? '' : `, through P${sub(m.watched.through)}`;
  return `${knotsSaid(m)}: ${agreement(m.watched)}: ${verdict(m)}${through}`;
}

/** The derivatives left and right of the watched knot, each row said equal or not. */
export function joinTex(m: ContinuityModel, narrowBox = false): string {
  const check = m.watched;
  const c = words(check.u);
  // One column per derivative, left and right under it: three rows whatever
  // the degree, so the figure keeps its room on the projector.
  // Each head says whether the column's two values agree, as the figure names
  // them: P′(5⁻) ≠ P′(5⁺) ("P : =" was read as "P is defined as").
  const heads = check.left.map((_, r) => {
    const d = derivativeTex(r);
    return `${d}(${c}^-) ${check.agree[r] ? '=' : '\\ne'} ${d}(${c}^+)`;
  });
  const side = (values: typeof check.left) => values.map((v) => pt(v)).join(' & ');
  const smooth =
    check.smooth === Infinity
      ? 'C^{\\infty}'
      : check.smooth < 0
        ? '\\text{a jump}'
        : `C^{${check.smooth}}`;
  const through = check.through === null ? '' : `,\\quad P(${c}) = P_{${check.through}}`;
  const verdict = `\\;\\Rightarrow\\; ${smooth}${through}`;
  if (narrowBox) {
    // On its side: one row per derivative, its two values and = or ≠ between
    // them (a laptop's panel: four columns of points ran 589 px in 404).
    const rows = check.left.map(
      (left, r) =>
        `${derivativeTex(r)} & ${pt(left)} & ${check.agree[r] ? '=' : '\\ne'} & ${pt(check.right[r])}`,
    );
    return `\\begin{array}{r|ccc} & u \\to ${c}^- & & u \\to ${c}^+ \\\\ \\hline ${rows.join(' \\\\ ')}\\end{array}${verdict}`;
  }
  const columns = 'c'.repeat(check.left.length);
  return `\\begin{array}{r|${columns}} & ${heads.join(' & ')} \\\\ \\hline u \\to ${c}^- & ${side(check.left)} \\\\ u \\to ${c}^+ & ${side(check.right)}\\end{array}${verdict}`;
}

/** One case of the continuity walk: its caption, the derivatives as a table, on its side in the panel. */
const joinStep = (name: Exclude<ContinuityReveal, 'points'>) =>
  narrow(
    step<BSplineState, ContinuityModel, ContinuityReveal>(
      name,
      ({ model }) => caseCaption(model),
      ({ model }) => joinTex(model),
    ),
    ({ model }) => joinTex(model, true),
  );

/**
 * Degree p ⇒ Cᵖ⁻¹: the same points with degree 1, 2 and 3 on simple knots,
 * then the cubic with a double and a triple knot; at each, the derivatives of
 * the pieces either side of the watched knot compared.
 */
export const continuityScript = script<BSplineState, ContinuityModel, ContinuityReveal>(
  step('points', ({ state }) => {
    const n = state.points.length;
    return `The m + 1 = ${n} control points P0 … P${n - 1}: curves of degree 1, 2 and 3 come next`;
  }),
  ...(['linear', 'quadratic', 'cubic', 'double', 'triple'] as const).map(joinStep),
);
