import { trimmed } from '../../kit/format';
import type { Point } from '../../math';
import { sameCountReasons } from './likelyWhy';
import { readPoints } from './pastedPoints';
import {
  type SplineKind,
  TOLERANCE,
  agree,
  amount,
  expectedOutput,
  rowName,
  within,
} from './splineRows';

// "Check your computeSplineC1/C2 output": the student pastes the control
// points their program printed, as plain numbers, and learns which rows differ
// from the spline the practical asks for, by how much, and the likely why.
// Pure: text in, a verdict out; never throws on any text.

export type { SplineKind } from './splineRows';

export interface Difference {
  /** The row of the pasted output (0-based, as the program's matrix numbers it). */
  row: number;
  /** The control point that row should hold: p₂, b₁, E, c₇. */
  name: string;
  expected: Point;
  got: Point;
  /** |got − expected| (NaN where a coordinate is not a number). */
  distance: number;
}

export interface Verdict {
  /** pass: every row within 1e-6; rounded: within the digits printed; fail; unreadable: not numbers. */
  status: 'pass' | 'rounded' | 'fail' | 'unreadable';
  summary: string;
  /** Likely reasons, most likely first. */
  why: string[];
  differences: Difference[];
}

interface Compared {
  differences: Difference[];
  /** Every coordinate within 1e-6. */
  strict: boolean;
  /** The largest coordinate difference. */
  largest: number;
}

/** Row by row: `rows[r]` is the expected index the pasted row r should hold. */
function compare(
  got: readonly Point[],
  slack: readonly Point[],
  expected: readonly Point[],
  name: (j: number) => string,
  rows: readonly number[] = got.map((_, r) => r),
): Compared {
  const differences: Difference[] = [];
  let largest = 0;
  rows.forEach((j, r) => {
    const [g, e] = [got[r], expected[j]];
    const gaps = g.map((v, d) => Math.abs(v - e[d]));
    largest = Math.max(largest, ...gaps.map((gap) => (Number.isNaN(gap) ? Infinity : gap)));
    if (!g.every((v, d) => within(v, e[d], slack[r][d])))
      differences.push({
        row: r,
        name: name(j),
        expected: e,
        got: g,
        distance: Math.hypot(g[0] - e[0], g[1] - e[1]),
      });
  });
  return { differences, strict: largest <= TOLERANCE, largest };
}

const countFormula = (kind: SplineKind, n: number) =>
  kind === 'C1' ? `2n + 1 = ${2 * n + 1}` : `3n + 1 = ${3 * n + 1}`;
const functionName = (kind: SplineKind) => (kind === 'C1' ? 'computeSplineC1' : 'computeSplineC2');

/** The rows `got` would be with one repeated joint per piece dropped, or null. */
function withoutRepeatedJoints(got: readonly Point[], perPiece: number, slack: readonly Point[]) {
  const pieces = got.length / perPiece;
  if (!Number.isInteger(pieces) || pieces < 2) return null;
  for (let i = 1; i < pieces; i++) {
    const [end, start] = [got[i * perPiece - 1], got[i * perPiece]];
    if (!end.every((v, d) => within(v, start[d], slack[i * perPiece][d]))) return null;
  }
  const keep = got.flatMap((_, r) => (r % perPiece === 0 && r > 0 ? [] : [r]));
  return keep;
}

function otherCount(
  p: readonly Point[],
  kind: SplineKind,
  got: readonly Point[],
  slack: readonly Point[],
  expected: readonly Point[],
  notes: string[],
): Verdict {
  const n = p.length - 1;
  const m = got.length;
  const name = (j: number) => rowName(j, kind, n);
  const summary = `Expected ${countFormula(kind, n)} control points for n = ${n} pieces through ${n + 1} points; got ${m}.`;
  const fail = (why: string[], differences: Difference[] = []): Verdict => ({
    status: 'fail',
    summary,
    why: [...notes, ...why],
    differences,
  });
  const degree = kind === 'C1' ? 2 : 3;
  if (m === n + 1)
    return fail([
      agree(got, p, slack)
        ? `These are the ${n + 1} given points themselves, not the control points: ${functionName(kind)} returns ${countFormula(kind, n)} rows, the given points every ${degree === 2 ? 'second' : 'third'} row.`
        : `${n + 1} rows, as many as the given points: ${functionName(kind)} returns ${countFormula(kind, n)}, the given points every ${degree === 2 ? 'second' : 'third'} row.`,
    ]);
  const other: SplineKind = kind === 'C1' ? 'C2' : 'C1';
  if (m === expectedOutput(p, other).length)
    return fail([
      agree(got, expectedOutput(p, other), slack)
        ? `These are the ${other === 'C1' ? 'C¹' : 'C²'} spline’s control points: choose ${other === 'C1' ? 'C¹' : 'C²'} above.`
        : `${countFormula(other, n)} is what ${functionName(other)} returns; ${functionName(kind)} returns ${countFormula(kind, n)}. Is the right spline chosen above?`,
    ]);
  // Each piece's control points in full, the joints twice.
  if (m === (degree + 1) * n) {
    const rows = withoutRepeatedJoints(got, degree + 1, slack);
    const why = `Each piece’s ${degree + 1} control points listed separately, every inner joint twice (${m} rows): ${functionName(kind)} shares the joints, ${countFormula(kind, n)} rows.`;
    if (rows) {
      const index = rows.map((r) => r - Math.floor(r / (degree + 1)));
      const kept = rows.map((r) => got[r]);
      const keptSlack = rows.map((r) => slack[r]);
      const compared = compare(kept, keptSlack, expected, name, index);
      const differences = compared.differences.map((d) => ({ ...d, row: rows[d.row] }));
      return fail(
        [
          why,
          differences.length === 0
            ? `Read without the repeats, all ${expected.length} control points agree.`
            : `Read without the repeats, ${differences.length} differ.`,
        ],
        differences,
      );
    }
    return fail([why]);
  }
  // Only the unknown control points.
  if (m === (degree - 1) * n) {
    const index = expected.flatMap((_, j) => (j % degree === 0 ? [] : [j]));
    const compared = compare(got, slack, expected, name, index);
    return fail(
      [
        `${m} rows: only the ${kind === 'C1' ? 'bᵢ' : 'inner control points'}? ${functionName(kind)} returns them with the given points between, ${countFormula(kind, n)} rows.`,
        compared.differences.length === 0
          ? `Read as the inner control points, all ${m} agree.`
          : `Read as the inner control points, ${compared.differences.length} differ.`,
      ],
      compared.differences,
    );
  }
  if (Math.abs(m - expected.length) === 1) {
    const fewer = m < expected.length;
    const without = <T>(list: readonly T[], k: number) => list.filter((_, j) => j !== k);
    // The one row that, left out of the longer list, makes the two agree.
    const at = (fewer ? expected : got).findIndex((_, k) =>
      fewer
        ? agree(got, without(expected, k), slack)
        : agree(without(got, k), expected, without(slack, k)),
    );
    if (at >= 0)
      return fail([
        fewer
          ? `Row ${at} (${name(at)}) is missing; the others agree: a loop that stops one step early, or starts one late?`
          : `Row ${at} is one too many; the others agree: a loop that runs one step too far?`,
      ]);
    return fail([
      fewer
        ? 'One row too few: a loop that stops one step early?'
        : 'One row too many: a loop that runs one step too far?',
    ]);
  }
  return fail([]);
}

/** Checks pasted output against what computeSplineC1 or computeSplineC2 should print for `points`. */
export function checkOutput(text: string, points: readonly Point[], kind: SplineKind): Verdict {
  const n = points.length - 1;
  const expected = expectedOutput(points, kind);
  const read = readPoints(text, expected.length);
  if (!read.ok) return { status: 'unreadable', summary: read.message, why: [], differences: [] };
  const notes = read.transposed
    ? [
        `Read as two rows, all x then all y: a 2 × ${expected.length} matrix, the practical’s output turned over (it has one control point per row).`,
      ]
    : [];
  const { points: got, slack } = read;
  if (got.length !== expected.length) return otherCount(points, kind, got, slack, expected, notes);
  const name = (j: number) => rowName(j, kind, n);
  const compared = compare(got, slack, expected, name);
  const count = expected.length;
  if (compared.strict)
    return {
      status: 'pass',
      summary: `All ${count} control points agree to 1e-6.`,
      why: notes,
      differences: [],
    };
  if (compared.differences.length === 0)
    return {
      status: 'rounded',
      summary: `All ${count} control points agree to the digits printed (the largest difference, ${amount(compared.largest)}, is rounding); print more digits, e.g. std::setprecision(10), to check them to 1e-6.`,
      why: notes,
      differences: [],
    };
  const [first] = compared.differences;
  return {
    status: 'fail',
    summary: `${compared.differences.length} of ${count} control points differ; the first is row ${first.row} (${first.name}), ${Number.isNaN(first.distance) ? 'not a number' : `by ${amount(first.distance)}`}.`,
    why: [...notes, ...sameCountReasons(points, kind, got, slack, expected)],
    differences: compared.differences,
  };
}

/** The table of differences as the panel shows it: row, name, expected, yours, by how much. */
export function differenceRows(verdict: Verdict): string[][] {
  const point = (q: Point) => `(${q.map((v) => trimmed(v, 6).replace('-', '−')).join(', ')})`;
  return verdict.differences.map((d) => [
    String(d.row),
    d.name,
    point(d.expected),
    point(d.got),
    amount(d.distance),
  ]);
}
