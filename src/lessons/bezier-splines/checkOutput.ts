import { pointWords, sub, trimmed, words } from '../../kit/format';
import {
  type Point,
  type SplineEquation,
  controlPointName,
  cubicSplineC2System,
  quadraticSplineC1,
  solveDense,
} from '../../math';
import { midpoint } from './state';

// "Check your computeSplineC1/C2 output": the student pastes the control
// points their program printed, as plain numbers, and learns which rows differ
// from the spline the practical asks for, by how much, and the likely why.
// Pure: text in, a verdict out; never throws on any text.

export type SplineKind = 'C1' | 'C2';
/** Control points that agree this closely agree. */
export const TOLERANCE = 1e-6;

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

// ---------------------------------------------------------------- reading

type Read =
  | { ok: true; points: Point[]; slack: Point[]; transposed: boolean }
  | { ok: false; message: string };

const SEPARATORS = /[\s,;()[\]{}]+/;
const NUMBER = /^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?$/;
// What C, C++ and Python print for a failed computation.
const NOT_FINITE = /^[+-]?(?:nan|inf|infinity)$/i;

/**
 * How far a printed number may be from the value it stands for. 0.111111
 * stands for anything within 5·10⁻⁷; a whole number such as 2, as printed by
 * C++'s default six significant digits, for anything within 5·10⁻⁶ of it.
 */
export function printedSlack(token: string): number {
  if (NOT_FINITE.test(token)) return 0;
  const [mantissa, exponent = '0'] = token.toLowerCase().split('e');
  if (mantissa.includes('.')) {
    const decimals = mantissa.split('.')[1].length - Number(exponent);
    return 0.5 * 10 ** -decimals;
  }
  const value = Math.abs(Number(token));
  return value === 0 ? 0 : 0.5 * 10 ** (Math.floor(Math.log10(value)) - 5);
}

/** A token's value: nan is NaN, inf ±Infinity (Number('inf') would be NaN). */
const valueOf = (token: string) =>
  NOT_FINITE.test(token) && !/nan/i.test(token)
    ? (token.startsWith('-') ? -1 : 1) * Infinity
    : Number(token);

const shorten = (token: string) => (token.length > 24 ? `${token.slice(0, 24)}…` : token);

/**
 * The numbers of `text` as x y points. Separators: any whitespace, commas,
 * semicolons, brackets, new lines. Two lines of `rows` numbers each are read
 * as a 2 × rows matrix (all x, then all y), as Eigen prints the transpose.
 */
export function readPoints(text: string, rows = 0): Read {
  // A true minus sign (from a document) and Windows' "-nan(ind)" read as C prints them.
  const cleaned = text.replace(/[\u2212\u2012\u2013]/g, '-').replace(/nan\([a-z]*\)/gi, 'nan');
  const lines: { numbers: number[]; tokens: string[] }[] = [];
  const all = cleaned.split(/\r\n|\r|\n/);
  for (let line = 0; line < all.length; line++) {
    const tokens = all[line].split(SEPARATORS).filter(Boolean);
    for (const token of tokens) {
      if (!NUMBER.test(token) && !NOT_FINITE.test(token))
        return {
          ok: false,
          message: `“${shorten(token)}” on line ${line + 1} is not a number. Paste only the numbers your program printed, x and y of each control point; spaces, commas, semicolons, brackets and new lines may separate them.`,
        };
    }
    if (tokens.length > 0) lines.push({ numbers: tokens.map(valueOf), tokens });
  }
  const numbers = lines.flatMap((l) => l.numbers);
  const tokens = lines.flatMap((l) => l.tokens);
  if (numbers.length === 0)
    return {
      ok: false,
      message:
        'No numbers yet: paste the control points your computeSplineC1 or computeSplineC2 printed, x and y of each.',
    };
  const transposed =
    rows > 2 &&
    lines.length === 2 &&
    lines[0].numbers.length === rows &&
    lines[1].numbers.length === rows;
  if (transposed) {
    const [xs, ys] = lines;
    return {
      ok: true,
      transposed,
      points: xs.numbers.map((x, j) => [x, ys.numbers[j]]),
      slack: xs.tokens.map((x, j) => [printedSlack(x), printedSlack(ys.tokens[j])]),
    };
  }
  if (numbers.length % 2 === 1)
    return {
      ok: false,
      message: `${numbers.length} numbers do not pair into x y points: one is missing or one too many (the last, ${shorten(tokens[tokens.length - 1])}, has no partner).`,
    };
  return {
    ok: true,
    transposed,
    points: Array.from({ length: numbers.length / 2 }, (_, j) => [
      numbers[2 * j],
      numbers[2 * j + 1],
    ]),
    slack: Array.from({ length: numbers.length / 2 }, (_, j) => [
      printedSlack(tokens[2 * j]),
      printedSlack(tokens[2 * j + 1]),
    ]),
  };
}

// ---------------------------------------------------------------- what the practical asks for

/** computeSplineC1's rows: p₀, b₀, p₁, b₁, …, pₙ, with b₀ the midpoint of p₀p₁ (the practical's suggestion). */
const c1Output = (
  p: readonly Point[],
  rule = (i: number, previous: Point): Point => [
    2 * p[i][0] - previous[0],
    2 * p[i][1] - previous[1],
  ],
) => {
  const b: Point[] = [midpoint(p[0], p[1])];
  for (let i = 1; i < p.length - 1; i++) b.push(rule(i, b[i - 1]));
  return p.flatMap((q, i) => (i < b.length ? [q, b[i]] : [q]));
};

/** The C² system's solution, or null where a (mistaken) system is singular. */
function solve(equations: readonly SplineEquation[]): Point[] | null {
  try {
    const x = solveDense(
      equations.map((e) => e.coefficients),
      equations.map((e) => e.right),
    );
    return x.every((q) => q.every(Number.isFinite)) ? x : null;
  } catch {
    return null;
  }
}

/** The rows computeSplineC1 (2n + 1) or computeSplineC2 (3n + 1) should print for these points. */
export function expectedOutput(points: readonly Point[], kind: SplineKind): Point[] {
  if (kind === 'C1') {
    // The maths module's spline, the lesson's one source of truth.
    const pieces = quadraticSplineC1(points, midpoint(points[0], points[1]));
    return [points[0], ...pieces.flatMap((s) => s.slice(1))];
  }
  return solve(cubicSplineC2System(points)) ?? [];
}

/** The name of row j: pᵢ and bᵢ in turn for C¹; A … J (four points) or cⱼ for C². */
export function rowName(j: number, kind: SplineKind, n: number): string {
  if (kind === 'C1') return j % 2 === 0 ? `p${sub(j / 2)}` : `b${sub((j - 1) / 2)}`;
  const name = controlPointName(j, 3 * n + 1);
  return name.length === 1 ? name : `c${sub(j)}`;
}

// ---------------------------------------------------------------- comparing

const within = (got: number, expected: number, slack: number) =>
  Math.abs(got - expected) <= Math.max(TOLERANCE, slack * (1 + 1e-9));

/** Every coordinate within 1e-6 or the printing of that number (slack 0: within 1e-6). */
function agree(got: readonly Point[], expected: readonly Point[], slack?: readonly Point[]) {
  return (
    got.length === expected.length &&
    got.every((q, j) => q.every((v, d) => within(v, expected[j][d], slack?.[j][d] ?? 0)))
  );
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

/** A small amount as a reader writes it: 0.25, 3.2e−6. */
export const amount = (v: number) =>
  Number.isNaN(v)
    ? 'not a number'
    : v !== 0 && Math.abs(v) < 1e-3
      ? v.toExponential(1).replace('-', '−')
      : words(v);

// ---------------------------------------------------------------- likely reasons

interface Mistake {
  why: string;
  output: Point[] | null;
}

/** computeSplineC1 as it comes out with a common slip in bᵢ = 2pᵢ − bᵢ₋₁. */
function c1Mistakes(p: readonly Point[]): Mistake[] {
  const n = p.length - 1;
  const rule = (f: (i: number, prev: Point) => Point) => c1Output(p, f);
  const minus = (a: Point, b: Point): Point => [a[0] - b[0], a[1] - b[1]];
  const twice = (a: Point): Point => [2 * a[0], 2 * a[1]];
  return [
    {
      why: 'Forgot the factor 2: your bᵢ = pᵢ − bᵢ₋₁. C¹ makes pᵢ the midpoint of bᵢ₋₁ and bᵢ, so bᵢ = 2pᵢ − bᵢ₋₁.',
      output: rule((i, prev) => minus(p[i], prev)),
    },
    {
      why: 'C¹ from the wrong side, a mirrored tangent: your bᵢ = bᵢ₋₁, so the second piece leaves pᵢ back the way the first came in. C¹ asks pᵢ − bᵢ₋₁ = bᵢ − pᵢ.',
      output: rule((_i, prev) => prev.slice()),
    },
    {
      why: 'Mirrored the wrong way: your bᵢ = 2bᵢ₋₁ − pᵢ reflects pᵢ through bᵢ₋₁. Reflect bᵢ₋₁ through pᵢ: bᵢ = 2pᵢ − bᵢ₋₁.',
      output: rule((i, prev) => minus(twice(prev), p[i])),
    },
    {
      why: 'Off by one piece: your bᵢ = 2pᵢ₊₁ − bᵢ₋₁ reflects through the far end of piece i. Pieces i − 1 and i meet at pᵢ: bᵢ = 2pᵢ − bᵢ₋₁.',
      output: rule((i, prev) => minus(twice(p[Math.min(i + 1, n)]), prev)),
    },
    {
      why: 'Off by one piece: your bᵢ = 2pᵢ₋₁ − bᵢ₋₁ reflects through the start of piece i − 1. Pieces i − 1 and i meet at pᵢ: bᵢ = 2pᵢ − bᵢ₋₁.',
      output: rule((i, prev) => minus(twice(p[i - 1]), prev)),
    },
  ];
}

/** computeSplineC2 as it comes out with a common slip in one kind of row of the system. */
function c2Mistakes(p: readonly Point[]): Mistake[] {
  const n = p.length - 1;
  const c = (j: number) => rowName(j, 'C2', n);
  const system = cubicSplineC2System(p);
  const size = 3 * n + 1;
  const row = (terms: [number, number][]) => {
    const coefficients = new Array<number>(size).fill(0);
    for (const [j, v] of terms) if (j >= 0 && j < size) coefficients[j] = v;
    return coefficients;
  };
  const changed = (kind: SplineEquation['kind'], make: (e: SplineEquation) => number[] | null) =>
    solve(
      system.map((e) => {
        const coefficients = e.kind === kind ? make(e) : null;
        return coefficients ? { ...e, coefficients } : e;
      }),
    );
  // Names at the first inner joint (D for four points), as the practical writes them.
  const [k, m] = [3, 3 * n];
  return [
    {
      why: `C¹ from the wrong side, a mirrored tangent: your ${c(k + 1)} = ${c(k - 1)}, so the second piece leaves ${c(k)} back the way the first came in. C¹ is ${c(k - 1)} − 2${c(k)} + ${c(k + 1)} = 0.`,
      output: changed('C1', (e) =>
        row([
          [3 * e.at - 1, 1],
          [3 * e.at + 1, -1],
        ]),
      ),
    },
    {
      why: `Forgot the factor 2 in C¹: ${c(k - 1)} − 2${c(k)} + ${c(k + 1)} = 0 (${c(k)} is the midpoint of ${c(k - 1)} and ${c(k + 1)}).`,
      output: changed('C1', (e) =>
        row([
          [3 * e.at - 1, 1],
          [3 * e.at, -1],
          [3 * e.at + 1, 1],
        ]),
      ),
    },
    {
      why: `Forgot the factors 2 in C²: ${c(k - 2)} − 2${c(k - 1)} + 2${c(k + 1)} − ${c(k + 2)} = 0.`,
      output: changed('C2', (e) =>
        row([
          [3 * e.at - 2, 1],
          [3 * e.at - 1, -1],
          [3 * e.at + 1, 1],
          [3 * e.at + 2, -1],
        ]),
      ),
    },
    {
      why: `C² from the wrong side: your second derivatives at ${c(k)} are opposite (${c(k - 2)} − 2${c(k - 1)} + ${c(k)} = −(${c(k)} − 2${c(k + 1)} + ${c(k + 2)})). C² asks them equal: ${c(k - 2)} − 2${c(k - 1)} + 2${c(k + 1)} − ${c(k + 2)} = 0.`,
      output: changed('C2', (e) =>
        row([
          [3 * e.at - 2, 1],
          [3 * e.at - 1, -2],
          [3 * e.at, 2],
          [3 * e.at + 1, -2],
          [3 * e.at + 2, 1],
        ]),
      ),
    },
    {
      why: `The natural end is one index early: it is ${c(m - 2)} − 2${c(m - 1)} + ${c(m)} = 0, the last three control points.`,
      output: changed('natural', (e) =>
        e.at === 0
          ? null
          : row([
              [m - 3, 1],
              [m - 2, -2],
              [m - 1, 1],
            ]),
      ),
    },
    {
      why: `The natural start is one index late: it is ${c(0)} − 2${c(1)} + ${c(2)} = 0, the first three control points.`,
      output: changed('natural', (e) =>
        e.at !== 0
          ? null
          : row([
              [1, 1],
              [2, -2],
              [3, 1],
            ]),
      ),
    },
    {
      why: `The points went to the first ${n + 1} control points: point pᵢ is control point 3i (${p.map((_, i) => c(3 * i)).join(', ')}), so its 1 goes in column 3i of row i.`,
      output: changed('point', (e) => row([[e.at, 1]])),
    },
  ];
}

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

function sameCountReasons(
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

// ---------------------------------------------------------------- the verdict

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
