import { pointWords, sub } from '../../kit/format';
import { type Point, type SplineEquation, cubicSplineC2System } from '../../math';
import { c1Mistakes, c2Mistakes } from './mistakes';
import { type SplineKind, TOLERANCE, agree, amount, rowName, within } from './splineRows';
import { midpoint } from './state';

// Why pasted output with the right number of rows differs: a common slip it
// matches, or else the equations (C²) or steps (C¹) its numbers break.

/** The equation a row of the system says, in the practical's letters: "B − 2C + 2E − F". */
function equationText(e: SplineEquation, n: number): string {
  const terms = e.coefficients.flatMap((v, j) => {
    if (v === 0) return [];
    const size = Math.abs(v) === 1 ? '' : String(Math.abs(v));
    return [{ sign: v < 0 ? '−' : '+', text: `${size}${rowName(j, 'C2', n)}` }];
  });
  return terms
    .map((t, i) => (i === 0 ? (t.sign === '−' ? `−${t.text}` : t.text) : ` ${t.sign} ${t.text}`))
    .join('');
}

const where = (e: SplineEquation, n: number) => {
  const at = rowName(3 * e.at, 'C2', n);
  if (e.kind === 'C1') return `C¹ at ${at}`;
  if (e.kind === 'C2') return `C² at ${at}`;
  return e.at === 0 ? 'the natural start' : 'the natural end';
};

/** C²: the equations of the practical's system the pasted rows do not satisfy. */
function unmetEquations(p: readonly Point[], got: readonly Point[], slack: readonly Point[]) {
  const n = p.length - 1;
  const out: string[] = [];
  for (const e of cubicSplineC2System(p)) {
    const residual = e.right.map((r, d) =>
      e.coefficients.reduce((sum, v, j) => sum + v * got[j][d], -r),
    );
    const allowed = e.right.map((_, d) =>
      e.coefficients.reduce((sum, v, j) => sum + Math.abs(v) * Math.max(TOLERANCE, slack[j][d]), 0),
    );
    if (residual.every((v, d) => Math.abs(v) <= allowed[d] * (1 + 1e-9))) continue;
    if (e.kind === 'point') {
      out.push(
        `Row ${3 * e.at} (${rowName(3 * e.at, 'C2', n)}) should be the point p${sub(e.at)} = ${pointWords(p[e.at])}: rows 0, 3, 6, … are the given points.`,
      );
    } else {
      out.push(
        `${where(e, n).replace(/^./, (s) => s.toUpperCase())}: ${equationText(e, n)} = 0 does not hold for your numbers (it gives (${residual.map(amount).join(', ')})).`,
      );
    }
  }
  return out;
}

/** C¹: the joints, b₀, and the first bᵢ that does not follow from the one before. */
function unmetSteps(p: readonly Point[], got: readonly Point[], slack: readonly Point[]) {
  const n = p.length - 1;
  const out: string[] = [];
  const near = (j: number, e: Point) => got[j].every((v, d) => within(v, e[d], slack[j][d]));
  const joints = p.flatMap((q, i) => (near(2 * i, q) ? [] : [i]));
  for (const i of joints.slice(0, 3))
    out.push(
      `Row ${2 * i} should be the point p${sub(i)} = ${pointWords(p[i])}: rows 0, 2, 4, … are the given points.`,
    );
  const mid = midpoint(p[0], p[1]);
  const follows = (i: number) =>
    near(2 * i + 1, [2 * p[i][0] - got[2 * i - 1][0], 2 * p[i][1] - got[2 * i - 1][1]]);
  const broken = Array.from({ length: n - 1 }, (_, k) => k + 1).find((i) => !follows(i));
  if (!near(1, mid)) {
    out.push(
      `b₀ (row 1) is ${pointWords(got[1])}, not the midpoint ½(p₀ + p₁) = ${pointWords(mid)}, the practical’s suggestion this check uses.`,
    );
    if (broken === undefined && n > 1)
      out.push('Every later bᵢ follows correctly from your b₀ by bᵢ = 2pᵢ − bᵢ₋₁.');
  }
  if (broken !== undefined) {
    const j = 2 * broken + 1;
    out.push(
      `Row ${j} (b${sub(broken)}) does not follow from your own b${sub(broken - 1)} = ${pointWords(got[j - 2])}: 2p${sub(broken)} − b${sub(broken - 1)} = ${pointWords([2 * p[broken][0] - got[j - 2][0], 2 * p[broken][1] - got[j - 2][1]])}.`,
    );
  }
  return out;
}

export function sameCountReasons(
  p: readonly Point[],
  kind: SplineKind,
  got: readonly Point[],
  slack: readonly Point[],
  expected: readonly Point[],
): string[] {
  const n = p.length - 1;
  const why: string[] = [];
  const broken = got.findIndex((q) => !q.every(Number.isFinite));
  if (broken >= 0)
    why.push(
      `Row ${broken} (${rowName(broken, kind, n)}) is not a number (nan or inf): the values were used before they were set, or the system was singular.`,
    );
  const swapped = got.map(([x, y]) => [y, x]);
  if (
    agree(
      swapped,
      expected,
      slack.map(([x, y]) => [y, x]),
    )
  )
    return [...why, 'x and y are swapped: each row is x, then y.'];
  if (agree([...got].reverse(), expected, [...slack].reverse()))
    return [...why, 'The rows are in reverse order: row 0 is p₀, the last row pₙ.'];
  const mistakes = kind === 'C1' ? c1Mistakes(p) : c2Mistakes(p);
  const match = mistakes.find(
    (m) => m.output && !agree(m.output, expected) && agree(got, m.output, slack),
  );
  if (match) return [...why, match.why];
  if (broken >= 0) return why;
  return [...why, ...(kind === 'C1' ? unmetSteps(p, got, slack) : unmetEquations(p, got, slack))];
}
