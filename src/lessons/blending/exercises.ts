import {
  type ExerciseSpec,
  type Random,
  type Verdict,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { sub, words } from '../../kit/format';
import { type Point, bernstein, bernsteinBasis, bezierPoint, binomial } from '../../math';
import { blendingScript } from './bernsteinScript';
import type { BlendingState } from './state';

/** Values of μ a student can raise to a power by hand. */
const FRIENDLY_MU = [0.2, 0.25, 0.3, 0.4, 0.6, 0.7, 0.75, 0.8];

const SUPERSCRIPTS = '⁰¹²³⁴⁵⁶⁷⁸⁹';
/** 3 → "³": a power in plain text. */
const sup = (k: number) => [...String(k)].map((d) => SUPERSCRIPTS[Number(d)]).join('');

/** W(N, i, μ) = C(N, i)·μⁱ·(1 − μ)ᴺ⁻ⁱ in plain text, with N and i filled in. */
const formulaText = (n: number, i: number) =>
  `W(${n}, ${i}, μ) = ${binomial(n, i)}·μ${sup(i)}·(1 − μ)${sup(n - i)}`;

/**
 * N + 1 control points with integer coordinates: the two ends on the ground,
 * every inner point above them (never on one line, no two on one spot).
 */
export function controlPolygon(r: Random, n: number): Point[] {
  const spacing = n <= 3 ? 2 : 1;
  return Array.from({ length: n + 1 }, (_, i) => [
    spacing * i,
    i === 0 || i === n ? r.int(0, 1) : r.int(2, 4),
  ]);
}

/** The lesson's Bernstein script at μ, from step 0 (the points) to the traced curve. */
const walked = (defaults: BlendingState, p: Point[], mu: number): BlendingState => {
  const s: BlendingState = { ...defaults, p, mu, comparison: 'none' };
  return { ...s, step: blendingScript.lastStep(s) };
};

/**
 * Step 0 with the cursor at μ = 0: the points and their polygon, no weight,
 * no function, no P(μ). (The weights table always shows the weights at the
 * cursor: at μ = 0 they say nothing about the μ asked.)
 */
const pointsOnly = (defaults: BlendingState, p: Point[]): BlendingState => ({
  ...defaults,
  p,
  mu: 0,
  comparison: 'none',
  step: 0,
});

/** Compute one Bernstein weight by hand. */
const weight: ExerciseSpec<BlendingState> = {
  id: 'weight',
  title: 'A blending function’s value',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const n = r.pick([2, 3, 3, 4, 4, 5]);
    const i = r.int(1, n - 1);
    const mu = r.pick(FRIENDLY_MU);
    const name = `W(${n}, ${i}, ${words(mu)})`;
    const answer = [bernstein(n, i, mu)];
    const tolerance = 0.001;
    const c = binomial(n, i);
    const mistakes = [
      {
        values: [bernstein(n, i, 1 - mu)],
        hint: `μ goes with the power i = ${i} and 1 − μ with N − i = ${n - i}; you swapped μ and 1 − μ.`,
      },
      {
        values: [answer[0] / c],
        hint: `The binomial coefficient C(${n}, ${i}) = ${c} multiplies μ${sup(i)}·(1 − μ)${sup(n - i)}; you left it out.`,
      },
      {
        values: [bernstein(n + 1, i, mu)],
        hint: `N is the degree, ${n}, one less than the ${n + 1} control points.`,
      },
      ...[i - 1, i + 1].map((j) => ({
        values: [bernstein(n, j, mu)],
        hint: `That is W(${n}, ${j}, μ), the weight of P${sub(j)}; the points count from P₀, so P${sub(i)} has i = ${i}.`,
      })),
    ];
    const hint = `${formulaText(n, i)}: C(${n}, ${i}) = ${c}, then μ${sup(i)} and (1 − μ)${sup(n - i)} at μ = ${words(mu)}, then multiply the three.`;
    const p = controlPolygon(r, n);
    return {
      state: pointsOnly(defaults, p),
      prompt: `Compute the blending function ${name}, the weight of P${sub(i)} at μ = ${words(mu)} on a curve of degree N = ${n} (to 3 decimals).`,
      task: {
        kind: 'number',
        fields: [name],
        tolerance,
        answer,
        check: (values) => checkNumbers(values, answer, tolerance, hint, mistakes),
      },
      working: walked(defaults, p, mu),
    };
  },
};

/** Predict P(μ) as the weighted average of the control points. */
const blend: ExerciseSpec<BlendingState> = {
  id: 'blend',
  title: 'Where is P(μ)?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const n = r.pick([2, 3]);
    const mu = r.pick([0.25, 0.5, 0.75]);
    const p = controlPolygon(r, n);
    const answer = bezierPoint(p, mu);
    const tolerance = 0.2;
    const weights = bernsteinBasis(n, mu).map((w) => words(w));
    return {
      state: pointsOnly(defaults, p),
      prompt: `Where is P(${words(mu)}) = Σ W(${n}, i, ${words(mu)})·Pᵢ, the blend of these control points? Tap your guess; within ${words(tolerance)} of the point counts.`,
      task: pointTask(
        'curve',
        answer,
        tolerance,
        `At μ = ${words(mu)} the weights of P₀ … P${sub(n)} are ${weights.join(', ')}: P(μ) is the points averaged with these weights, pulled hardest by the largest.`,
      ),
      working: walked(defaults, p, mu),
    };
  },
};

/** Where the plot's W(N, i, μ) is highest: μ = i/N, the lecture's peak. */
const peak: ExerciseSpec<BlendingState> = {
  id: 'peak',
  title: 'Where does a weight peak?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const n = r.int(2, 6);
    const i = r.int(1, n - 1);
    // W(N, i, μ)' = 0 where i(1 − μ) = (N − i)μ: at μ = i/N.
    const top = i / n;
    const answer = [top, bernstein(n, i, top)];
    const tolerance = 0.05;
    const p = controlPolygon(r, n);
    const hint = (guess: Point): string =>
      Math.abs(guess[0] - top) <= tolerance
        ? `Right μ; the top is as high as ${formulaText(n, i)} at μ = ${i}/${n}, which is ${words(answer[1])}.`
        : `${formulaText(n, i)} grows with μ${sup(i)} and falls with (1 − μ)${sup(n - i)}: it is highest where μ : (1 − μ) = ${i} : ${n - i}.`;
    return {
      state: pointsOnly(defaults, p),
      prompt: `Where is the top of the blending function W(${n}, ${i}, μ) on the plot of μ against W? Tap your guess; within ${words(tolerance)} counts.`,
      task: pointTask('blending', answer, tolerance, hint),
      working: walked(defaults, p, Number(top.toFixed(4))),
    };
  },
};

/** Two weights within this share of the larger one count as equal. */
const EQUAL_SHARE = 0.05;

/** Drag μ to where two neighbouring weights are equal: P_i and P_{i+1} pull equally. */
const crossing: ExerciseSpec<BlendingState> = {
  id: 'crossing',
  title: 'Where two points pull equally',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const n = r.int(2, 6);
    const i = r.int(0, n - 1);
    // C(N, i)(1 − μ) = C(N, i + 1)μ where the two curves cross: μ = (i + 1)/(N + 1).
    const equal = (i + 1) / (n + 1);
    const starts = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9].filter(
      (mu) => Math.abs(mu - equal) >= 0.15,
    );
    const p = controlPolygon(r, n);
    const state = walked(defaults, p, r.pick(starts));
    const first = `W(${n}, ${i}, μ)`;
    const second = `W(${n}, ${i + 1}, μ)`;
    const check = (s: BlendingState): Verdict => {
      if (s.p.length !== n + 1)
        return {
          correct: false,
          message: `Keep N = ${n}: put back ${n + 1} control points (there are ${s.p.length} now).`,
        };
      const a = bernstein(n, i, s.mu);
      const b = bernstein(n, i + 1, s.mu);
      const values = `at μ = ${words(s.mu)}, ${first} = ${words(a)} and ${second} = ${words(b)}`;
      if (Math.max(a, b) === 0)
        return {
          correct: false,
          message: `Not yet: ${values}, equal but neither point pulls at all. Find where they are equal and above 0.`,
        };
      if (Math.abs(a - b) <= EQUAL_SHARE * Math.max(a, b))
        return { correct: true, message: `Correct: ${values}.` };
      // W(N, i + 1, μ)/W(N, i, μ) grows with μ: the heavier P_i asks for a larger μ.
      const heavier = a > b ? i : i + 1;
      return {
        correct: false,
        message: `Not yet: ${values}. P${sub(heavier)} still pulls harder, so move μ ${a > b ? 'right' : 'left'}.`,
      };
    };
    return {
      state,
      prompt: `Drag the cursor μ on the plot to where P${sub(i)} and P${sub(i + 1)} pull equally hard, ${first} = ${second} (within 5% of each other).`,
      task: {
        kind: 'construct',
        check,
        solution: { ...state, mu: Number(equal.toFixed(4)) },
      },
      working: walked(defaults, p, Number(equal.toFixed(4))),
    };
  },
};

/** The blending lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<BlendingState>[] = [weight, blend, peak, crossing];
