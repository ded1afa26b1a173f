/**
 * The road's exercises: the Hermite road between two villages (global p̄,
 * local p, the parabola gradients), the first rows of the Thomas sweep of the
 * natural spline, and the quadratic road worked back from the end it must meet.
 */
import {
  type ExerciseSpec,
  type Mistake,
  type Random,
  type Verdict,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { pointWords, sub, words } from '../../kit/format';
import { type Point, bezierDerivative, bezierPoint, distance } from '../../math';
import { type Road, buildRoad } from './roads';
import { roadScript } from './script';
import { buildSolve } from './solve';
import type { RoadState } from './state';

/** "P₀ (0, 4), P₁ (22, 14) and P₂ (40, 6)": the villages as the prompt lists them. */
function listed(villages: readonly Point[]): string {
  const names = villages.map((p, i) => `P${sub(i)} ${pointWords(p)}`);
  return `${names.slice(0, -1).join(', ')} and ${names[names.length - 1]}`;
}

/** The village at `k` km east of the coast, give or take 6 km: even numbers, so halves stay whole. */
const eastOf = (r: Random, k: number) => (k === 0 ? 0 : 20 * k + 2 * r.int(-3, 3));

/** The Bézier pieces of a road that has them (every road these exercises ask about). */
function piecesOf(road: Road): Point[][] {
  if (road.kind !== 'pieces') throw new Error(`a road of pieces, not ${road.kind}`);
  return road.pieces;
}

/** A state of the lesson showing `road` through `villages`, at step 0, with nothing else on. */
const roadState = (defaults: RoadState, villages: Point[], road: RoadState['road']): RoadState => ({
  ...defaults,
  villages,
  road,
  view: 'road',
  ends: false,
  comb: false,
  pBar: 0,
  step: 0,
});

/** Within this distance (km on the map, about 1.2% of it) a guessed point is right. */
export const MIDPOINT_TOLERANCE = 1;

/**
 * Five villages with a hump (or a dip) over segment i: P(i) and P(i+1) high,
 * P(i−1) and P(i+2) low, so the gradients bend the road at least 2 km off the
 * chord's middle ((Dᵢ − Dᵢ₊₁)/8 with y-part ≥ (32 + 32)/32 = 2).
 */
function humpVillages(r: Random, segment: number): Point[] {
  const dip = r.next() < 0.5;
  return Array.from({ length: 5 }, (_, k) => {
    const high = k === segment || k === segment + 1;
    const y = 2 * (high !== dip ? r.int(16, 24) : r.int(0, 8));
    return [eastOf(r, k), y];
  });
}

const hermiteMidpoint: ExerciseSpec<RoadState> = {
  id: 'hermite-midpoint',
  title: 'Where is the Hermite road at p̄ = i + ½?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const segment = r.int(1, 2);
    const villages = humpVillages(r, segment);
    const pBar = segment + 0.5;
    // Step 0 shows the villages alone: no road, no gradient, no marker.
    const state = { ...roadState(defaults, villages, 'hermite'), pBar };
    const pieces = piecesOf(buildRoad('hermite', state));
    const answer = bezierPoint(pieces[segment], 0.5);
    const [a, b] = [villages[segment], villages[segment + 1]];
    const chordMiddle: Point = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
    const bend = [answer[0] - chordMiddle[0], answer[1] - chordMiddle[1]];
    const i = sub(segment);
    const j = sub(segment + 1);
    // Typical slips, each with the step it gets wrong.
    const slips: [Point, string][] = [
      [
        chordMiddle,
        `That is the middle of the straight line P${i}P${j}: the gradients bend the road by (D${i} − D${j})/8 at p = 0.5.`,
      ],
      [
        [chordMiddle[0] + 2 * bend[0], chordMiddle[1] + 2 * bend[1]],
        `Each gradient is half the chord between the neighbours, Dᵢ = (Pᵢ₊₁ − Pᵢ₋₁)/2: yours bend twice as far.`,
      ],
      [
        [chordMiddle[0] - bend[0], chordMiddle[1] - bend[1]],
        `Check the signs: at p = 0.5 the Hermite weights of P${i}, D${i}, P${j}, D${j} are ½, ⅛, ½ and −⅛.`,
      ],
      ...[segment - 1, segment + 1].map((other): [Point, string] => [
        bezierPoint(pieces[other], 0.5),
        `That is on segment ${other}: p̄ = ${words(pBar)} is segment ${segment} (from P${i} to P${j}) at p = 0.5.`,
      ]),
    ];
    const hint = (guess: Point) =>
      slips.find(([at]) => distance(guess, at) <= MIDPOINT_TOLERANCE)?.[1] ??
      `Work out D${i} and D${j} first, then P = ½(P${i} + P${j}) + ⅛(D${i} − D${j}).`;
    return {
      state,
      prompt: `The villages are ${listed(villages)}. On the Hermite road, with gradients Dᵢ = (Pᵢ₊₁ − Pᵢ₋₁)/2, where is the point at p̄ = ${words(pBar)} (within ${MIDPOINT_TOLERANCE} km)?`,
      task: pointTask('map', answer, MIDPOINT_TOLERANCE, hint),
      // The gradients, the road segment by segment, then the marker at p̄.
      working: state,
    };
  },
};

/** Γ₀ and Γ₁ are asked to two decimals. */
export const SWEEP_TOLERANCE = 0.01;

const thomasSweep: ExerciseSpec<RoadState> = {
  id: 'thomas-sweep',
  title: 'The first rows of the forward sweep',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const villages = Array.from({ length: 4 }, (_, k): Point => [eastOf(r, k), 2 * r.int(0, 20)]);
    // Step 0 shows the villages; the system and its sweep come with the next steps.
    const state = roadState(defaults, villages, 'natural');
    const { Gamma } = buildSolve(state)!.trace[0];
    const answer = [Gamma[0], Gamma[1]];
    const [x0, x1, x2] = villages.map((p) => p[0]);
    // Row 0 is [2 1 | d0], row 1 [1 4 1 | d1]; the slips below each get one of them wrong.
    const d0 = 3 * (x1 - x0);
    const d1 = 3 * (x2 - x0);
    const pivot = 4 - 1 / 2;
    const mistakes: Mistake[] = [
      {
        values: [(x1 - x0) / 2, (x2 - x0 - (x1 - x0) / 2) / pivot],
        hint: 'The right-hand sides are 3(x₁ − x₀) and 3(x₂ − x₀): the 3 comes from matching the second derivatives.',
      },
      {
        values: [d0, (d1 - d0) / 3],
        hint: 'Row 0 is [2 1 | 3(x₁ − x₀)]: divide it by its pivot 2 first, so γ₀ = ½ and Γ₀ = 3(x₁ − x₀)/2.',
      },
      {
        values: [d0 / 2, (d1 - d0 / 2) / 4],
        hint: 'Row 1’s pivot is b₁ − a₁γ₀ = 4 − ½ = 3.5, not 4.',
      },
      {
        values: [d0 / 2, d1 / pivot],
        hint: 'Subtract a₁Γ₀ = Γ₀ from row 1’s right-hand side before dividing by the pivot.',
      },
      {
        values: [d0 / 2, (3 * (x2 - x1) - d0 / 2) / pivot],
        hint: 'Row 1 is an inner row: its right-hand side is 3(x₂ − x₀), from the neighbours on both sides.',
      },
    ];
    return {
      state,
      prompt: `The natural road runs through P₀ … P₃ at x = ${[x0, x1, x2, villages[3][0]].map(words).join(', ')}. In the forward sweep of its system for x, what are Γ₀ and Γ₁ (to 2 decimals)?`,
      task: {
        kind: 'number',
        fields: ['Γ₀', 'Γ₁'],
        tolerance: SWEEP_TOLERANCE,
        answer,
        check: (values) =>
          checkNumbers(
            values,
            answer,
            SWEEP_TOLERANCE,
            'Sweep row by row: Γ₀ = d₀/b₀, then Γ₁ = (d₁ − a₁Γ₀)/(b₁ − a₁γ₀).',
            mistakes,
          ),
      },
      // The system, then the sweep row by row (γᵢ and Γᵢ for x in the caption), then back substitution.
      working: state,
    };
  },
};

/** How far the road's gradient at P₃ may be from the one asked for (B₀ within 1 km of its place). */
export const ARRIVAL_TOLERANCE = 2;

/** The gradient with which the quadratic road arrives at its last village. */
export function arrivalGradient(state: RoadState): Point {
  const pieces = piecesOf(buildRoad('quadratic', state));
  return bezierPoint(bezierDerivative(pieces[pieces.length - 1]), 1);
}

const sameVillages = (a: readonly Point[], b: readonly Point[]) =>
  a.length === b.length && a.every((p, i) => p[0] === b[i][0] && p[1] === b[i][1]);

const EVEN_OFFSETS = [-10, -8, -6, 6, 8, 10];

/**
 * Four villages and where B₀ must go: east of P₀ and below P₃, inside the
 * villages' box (so on the map). Drawn again while the road would arrive
 * with almost no gradient (no direction to meet a road along) or with one
 * over 100 (a swing far off the map).
 */
function arrivalData(r: Random): { villages: Point[]; first: Point } {
  for (;;) {
    const villages: Point[] = [
      [0, 2 * r.int(0, 5)],
      [eastOf(r, 1), 2 * r.int(0, 20)],
      [eastOf(r, 2), 2 * r.int(0, 20)],
      [eastOf(r, 3), 2 * r.int(12, 20)],
    ];
    const first: Point = [2 * r.int(2, 6), villages[0][1] + 2 * r.int(0, 5)];
    // D₃ = 2(P₃ − B₂) with B₂ = 2P₂ − 2P₁ + B₀ (B₁ = 2P₁ − B₀, B₂ = 2P₂ − B₁).
    const [, p1, p2, p3] = villages;
    const end = [0, 1].map((d) => 2 * (p3[d] - 2 * p2[d] + 2 * p1[d] - first[d]));
    if (Math.hypot(end[0], end[1]) >= 10 && Math.hypot(end[0], end[1]) <= 100)
      return { villages, first };
  }
}

const quadraticArrival: ExerciseSpec<RoadState> = {
  id: 'quadratic-arrival',
  title: 'Choose B₀ so the quadratic road meets the road at P₃',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const { villages, first } = arrivalData(r);
    const gradientAt = (b0: Point) => [2 * (b0[0] - villages[0][0]), 2 * (b0[1] - villages[0][1])];
    const built = (b0: Point): RoadState => {
      const state = {
        ...roadState(defaults, villages, 'quadratic'),
        quadraticGradient: gradientAt(b0),
      };
      // The whole road, with B₀'s handle: the construction steps show it.
      return { ...state, step: roadScript.lastStep(state) };
    };
    const solution = built(first);
    const target = arrivalGradient(solution);
    const start: Point = [first[0] + r.pick(EVEN_OFFSETS), first[1] + r.pick(EVEN_OFFSETS)];
    const m = villages.length - 1;
    const check = (s: RoadState): Verdict => {
      if (!sameVillages(s.villages, villages))
        return { correct: false, message: 'Keep the villages where they are: only B₀ moves.' };
      if (s.road !== 'quadratic' || s.view !== 'road')
        return { correct: false, message: 'Show the quadratic road again: this is about its B₀.' };
      const arrival = arrivalGradient(s);
      const off = distance(arrival, target);
      const now = `The road arrives at P${sub(m)} with D${sub(m)} = 2(P${sub(m)} − B${sub(m - 1)}) = ${pointWords(arrival)}, ${words(off)} from ${pointWords(target)}.`;
      return off <= ARRIVAL_TOLERANCE
        ? { correct: true, message: `Correct. ${now}` }
        : {
            correct: false,
            message: `Not yet. ${now} Work back from the end: B₂ = P₃ − D₃/2, then B₁ = 2P₂ − B₂ and B₀ = 2P₁ − B₁.`,
          };
    };
    return {
      state: built(start),
      prompt: `The villages are ${listed(villages)}. Drag B₀ so that the quadratic road arrives at P${sub(m)} with gradient D${sub(m)} = ${pointWords(target)}, within ${ARRIVAL_TOLERANCE}.`,
      task: { kind: 'construct', check, solution },
      // From B₀, each control point the reflection of the one before: B₁, B₂, and the end.
      working: { ...solution, step: 0 },
    };
  },
};

/** The road's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<RoadState>[] = [
  hermiteMidpoint,
  thomasSweep,
  quadraticArrival,
];
