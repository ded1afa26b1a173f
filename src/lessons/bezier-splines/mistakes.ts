import { type Point, type SplineEquation, cubicSplineC2System } from '../../math';
import { rowName, solve } from './splineRows';
import { midpoint } from './state';

// The slips a student's computeSplineC1 or computeSplineC2 commonly makes,
// each with the output it gives: pasted output that matches one is explained.

/** computeSplineC1's rows p₀, b₀, p₁, b₁, …, pₙ with b₀ the midpoint of p₀p₁ and each further bᵢ by `rule`. */
const c1Output = (p: readonly Point[], rule: (i: number, previous: Point) => Point) => {
  const b: Point[] = [midpoint(p[0], p[1])];
  for (let i = 1; i < p.length - 1; i++) b.push(rule(i, b[i - 1]));
  return p.flatMap((q, i) => (i < b.length ? [q, b[i]] : [q]));
};

export interface Mistake {
  why: string;
  output: Point[] | null;
}

/** computeSplineC1 as it comes out with a common slip in bᵢ = 2pᵢ − bᵢ₋₁. */
export function c1Mistakes(p: readonly Point[]): Mistake[] {
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
export function c2Mistakes(p: readonly Point[]): Mistake[] {
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
