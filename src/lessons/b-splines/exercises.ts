import {
  type ExerciseSpec,
  type Random,
  type Verdict,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { sub, words } from '../../kit/format';
import {
  type Point,
  clampedUniformKnots,
  coxDeBoorTable,
  distance,
  nurbsPoint,
  uniformBSplinePoint,
} from '../../math';
import { segmentName } from './notation';
import { partScript } from './scripts';
import type { BSplineState, Part } from './state';
import { pieceAt, uniformPieces } from './uniformPieces';

// The lesson's exercises: a point of one segment of the uniform cubic, an entry
// of the Cox–de Boor triangle on uneven knots, and knots stacked so that the
// curve passes through a control point.

const copy = (list: readonly Point[]): Point[] => list.map((point) => [...point]);

/** A state of a part with these points, degree and knots (every weight 1), at its step 0. */
function partState(
  defaults: BSplineState,
  part: Part,
  points: Point[],
  degree: number,
  knots: number[],
): BSplineState {
  return {
    ...defaults,
    part,
    points,
    before: copy(points),
    t: 0,
    step: 0,
    degree,
    knots,
    weights: points.map(() => 1),
    line: copy(defaults.line),
  };
}

/**
 * Seven points P0 … P6 of whole coordinates that zigzag along x: every other
 * one low (y 0 or 1), the others high (y 3 to 5), so no three lie on a line
 * and the curve keeps clear of every point (x = 2i, or 2i + 0/1 with `jitter`).
 */
function zigzag(r: Random, jitter: boolean): Point[] {
  const lowFirst = r.int(0, 1) === 0;
  return Array.from({ length: 7 }, (_, i) => {
    const low = (i % 2 === 0) === lowFirst;
    return [2 * i + (jitter ? r.int(0, 1) : 0), low ? r.int(0, 1) : r.int(3, 5)];
  });
}

const name = (i: number) => `P${sub(i)}`;
const list = (values: readonly number[]) => values.map(words).join(', ');

/** Where is Q_i(t)? The segment's four points blended by B0(t) … B3(t). */
const segmentPoint: ExerciseSpec<BSplineState> = {
  id: 'segment-point',
  title: 'Where is a point of a segment?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const points = zigzag(r, true);
    const first = r.int(0, 3);
    const local = r.pick([0.25, 0.5, 0.75]);
    // s = first + local on the whole curve: segment `first` (Q_{first+3}) at its local t.
    const answer = uniformBSplinePoint(points, first + local);
    const base = partState(defaults, 'uniform', points, 3, clampedUniformKnots(7, 3));
    const segment = segmentName(first).replace(/\d+/, (i) => sub(Number(i)));
    const blended = `${name(first)} … ${name(first + 3)}`;
    const tolerance = 0.3;
    return {
      // The polygon without the curve, the cursor at the far end (the panel's P(s) is not the answer).
      state: { ...base, t: first < 2 ? 1 : 0, step: 1 },
      prompt: `Segment ${segment} blends ${blended} with the bases B0(t) … B3(t). Where is its point ${segment}(${local}) (within ${tolerance})?`,
      task: pointTask(
        'curve',
        answer,
        tolerance,
        `Look again at the step “Segment ${segment} blends …”: the weights B0(${local}) … B3(${local}) are never negative and sum to 1, so ${segment}(${local}) lies among ${blended}, pulled most to the middle two.`,
      ),
      // The cursor at s = first + local of the m − 2 = 4 segments.
      working: { ...base, t: (first + local) / 4 },
    };
  },
};

/** Ten knots u0 … u9 from 0 in steps of 1 or 2, uneven around span j (so the recursion matters). */
function unevenKnots(r: Random, j: number): number[] {
  const gaps = Array.from({ length: 9 }, () => r.int(1, 2));
  // N(i,2) near span j reads u(j−2) … u(j+3): at least two different gaps there.
  const near = gaps.slice(j - 2, j + 3);
  if (near.every((gap) => gap === near[0])) gaps[j] = 3 - gaps[j];
  return gaps.reduce((knots, gap) => [...knots, knots[knots.length - 1] + gap], [0]);
}

/** An entry N(i,2)(u) of the Cox–de Boor triangle, on knots that are not equally spaced. */
const coxDeBoorEntry: ExerciseSpec<BSplineState> = {
  id: 'cox-de-boor',
  title: 'An entry of the Cox–de Boor triangle',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const points = zigzag(r, false);
    // Degree 2 on 7 points: knots u0 … u9, the curve on [u2, u7], spans j = 2 … 6.
    const j = r.int(2, 6);
    const knots = unevenKnots(r, j);
    const gap = knots[j + 1] - knots[j];
    const u = knots[j] + r.pick(gap === 1 ? [0.5] : [0.5, 1, 1.5]);
    const i = j - r.int(0, 2);
    const table = coxDeBoorTable(knots, 2, u);
    const answer = table[2][i];
    const base = partState(defaults, 'knots', points, 2, knots);
    const tolerance = 0.001;
    const entry = `N(${i},2)`;
    return {
      // The knots on the strip; the triangle's rows appear only from the next step.
      state: { ...base, t: (u - knots[2]) / (knots[7] - knots[2]), step: 1 },
      prompt: `On the knots u0 … u9 = ${list(knots)}, what is ${entry} at u = ${words(u)}? Give it to 3 decimals (within ${tolerance}).`,
      task: {
        kind: 'number',
        fields: [`${entry} at u = ${words(u)}`],
        tolerance,
        answer: [answer],
        check: (values) =>
          checkNumbers(
            values,
            [answer],
            tolerance,
            `Work the triangle row by row: row 0 is 1 only on [u${j}, u${j + 1}) where u lies, row 1 gives N(${i},1) and N(${i + 1},1), and ${entry} blends those two.`,
            coxDeBoorMistakes(knots, i, j, u, table),
          ),
      },
      working: { ...base, t: (u - knots[2]) / (knots[7] - knots[2]) },
    };
  },
};

/** The slips of the last step N(i,2) = rise·N(i,1) + fall·N(i+1,1), each with the step it names. */
function coxDeBoorMistakes(
  k: readonly number[],
  i: number,
  j: number,
  u: number,
  table: number[][],
) {
  const [left, right] = [table[1][i], table[1][i + 1]];
  // The notes' recursion with r = 2: (u − u_i)/(u_{i+2} − u_i) and (u_{i+3} − u)/(u_{i+3} − u_{i+1}).
  const rise = (u - k[i]) / (k[i + 2] - k[i]);
  const fall = (k[i + 3] - u) / (k[i + 3] - k[i + 1]);
  const piece = uniformPieces(2)[i - j + 2];
  const t = (u - k[j]) / (k[j + 1] - k[j]);
  return [
    {
      values: [fall * left + rise * right],
      hint: `Row 2 has its factors swapped: (u − u${i})/(u${i + 2} − u${i}) multiplies N(${i},1), and (u${i + 3} − u)/(u${i + 3} − u${i + 1}) multiplies N(${i + 1},1).`,
    },
    {
      values: [
        ((u - k[i]) / (k[i + 1] - k[i])) * left + ((k[i + 3] - u) / (k[i + 3] - k[i + 2])) * right,
      ],
      hint: `Row 2 divides by spans two knots wide: u${i + 2} − u${i} and u${i + 3} − u${i + 1}, not the one-knot spans of row 1.`,
    },
    {
      values: [pieceAt(piece, t)],
      hint: `That is the uniform piece of equally spaced knots; these knots are uneven, so work the recursion: row 1, then row 2.`,
    },
    {
      values: [left],
      hint: `That is row 1's N(${i},1); row 2 blends N(${i},1) and N(${i + 1},1).`,
    },
    ...[i - 1, i + 1]
      .filter((other) => other >= 0 && other < table[2].length)
      .map((other) => ({
        values: [table[2][other]],
        hint: `That is N(${other},2), the neighbour: N(${i},2) reads the knots u${i} … u${i + 3}.`,
      })),
  ];
}

/** How close the curve comes to a point: the least distance over its knots and 600 samples, and where. */
function closestApproach(state: BSplineState, target: Point): { gap: number; at: number } {
  const { points, weights, knots, degree } = state;
  const [a, b] = [knots[degree], knots[points.length]];
  const us = [
    ...knots.filter((u) => u >= a && u <= b),
    ...Array.from({ length: 601 }, (_, k) => a + ((b - a) * k) / 600),
  ];
  let best = { gap: Infinity, at: a };
  for (const u of us) {
    const gap = distance(nurbsPoint(points, weights, knots, degree, u), target);
    if (gap < best.gap) best = { gap, at: u };
  }
  return best;
}

/** Stack knots so that the cubic passes through a control point (multiplicity p = 3). */
const throughPoint: ExerciseSpec<BSplineState> = {
  id: 'through-point',
  title: 'Knots that make the curve touch a point',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const points = zigzag(r, false);
    const k = r.int(2, 4);
    const knots = Array.from({ length: 11 }, (_, j) => j);
    const base = partState(defaults, 'repeated', points, 3, knots);
    const state = { ...base, t: 0.5, step: partScript('repeated').lastStep(base) };
    // u(k+1) = u(k+2) = u(k+3): only N(k,3) is non-zero there, and it is 1.
    const stacked = knots.map((u, j) => (j >= k + 1 && j <= k + 3 ? k + 2 : u));
    const solution = { ...state, knots: stacked };
    const tolerance = 0.15;
    const check = (s: BSplineState): Verdict => {
      const { gap, at } = closestApproach(s, s.points[k]);
      const near = words(gap) === '0' ? 'through' : `within ${words(gap)} of`;
      return gap <= tolerance
        ? {
            correct: true,
            message: `Correct: the curve passes ${near} ${name(k)}, at u = ${words(at)}.`,
          }
        : {
            correct: false,
            message: `Not yet: the curve comes within ${words(gap)} of ${name(k)} (at u = ${words(at)}), more than ${tolerance}. A knot repeated p = 3 times makes the curve pass through a control point: stack the three knots strictly inside the span of N(${k},3), between u${k} and u${k + 4}.`,
          };
    };
    return {
      state,
      prompt: `Drag knots on the strip until the cubic B-spline passes through ${name(k)} (within ${tolerance}).`,
      task: { kind: 'construct', check, solution },
      working: { ...solution, t: (k + 2 - stacked[3]) / (stacked[7] - stacked[3]), step: 0 },
    };
  },
};

/** The lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<BSplineState>[] = [
  segmentPoint,
  coxDeBoorEntry,
  throughPoint,
];
