import {
  type ExerciseSpec,
  type Random,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { pointWords, words } from '../../kit/format';
import {
  distance,
  parametricQuadratic,
  parametricQuadraticPoint,
  pointBetween,
  type Point,
} from '../../math';
import { LAST_STEP, type QuadraticState } from './state';

// The lesson's practice: where P(μ) is for a chosen μ₁ (the family), P(μ)
// worked out from equations 2 and 3, and P₁ moved to steer a dot of equal μ.

/** Step 3 draws the curve with its dots at μ = 0, 0.1, …, 1 (script.ts, 'ticks'). */
const TICKS_STEP = 3;
/** How far a guessed point may be from P(μ): about 3% of the figure (some 7 units across). */
export const GUESS_TOLERANCE = 0.2;
/** How close the steered dot must come: about 1.5% of the figure, a finger's reach. */
export const STEER_TOLERANCE = 0.1;

/** Printed digits only: 1.6800000000000002 is shown, and checked, as 1.68. */
const clean = (p: readonly number[]) => p.map((v) => Number(v.toPrecision(12)));

/** Three integer points in an arch: P₁ at y 3 or 4, above the chord P₀P₂ (at most 2), between them in x. */
const arch = (r: Random): Point[] => [
  [0, r.int(0, 2)],
  [r.int(1, 3), r.int(3, 4)],
  [r.int(4, 6), r.int(0, 2)],
];
/** The arch upside down: a valley. */
const flip = (p: readonly Point[]): Point[] => p.map(([x, y]) => [x, 4 - y]);

/** Three integer points in an arch or a valley: P₁ 1 to 4 units off the chord P₀P₂, never on one line. */
export function threePoints(r: Random): Point[] {
  const p = arch(r);
  return r.next() < 0.5 ? p : flip(p);
}

/**
 * Points for steering: the goal, and the same with P₁ one unit off in x and
 * one or two further from the chord: still between P₀ and P₂ in x and off the
 * chord (never on one line or on another point), and the goal within the
 * figure the moved points open, in an arch or a valley alike.
 */
function steerPoints(r: Random): { goal: Point[]; points: Point[] } {
  const goal = arch(r);
  const [x, y] = goal[1];
  const dx = x === 1 ? 1 : x === 3 ? -1 : r.pick([-1, 1]);
  const dy = r.pick([1, 2]);
  const points = [goal[0], [x + dx, y + dy], goal[2]];
  return r.next() < 0.5 ? { goal, points } : { goal: flip(goal), points: flip(points) };
}

const at = (p: readonly Point[], mu1: number, mu: number) =>
  parametricQuadraticPoint(p[0], p[1], p[2], mu1, mu);

/** "P(μ) passes P₀ = (0, 1) at μ = 0, …": the data of a question, in one sentence. */
const passes = (p: readonly Point[], mu1: number) =>
  `P(μ) passes P₀ = ${pointWords(p[0])} at μ = 0, P₁ = ${pointWords(p[1])} at μ₁ = ${mu1} and P₂ = ${pointWords(p[2])} at μ = 1`;

const where: ExerciseSpec<QuadraticState> = {
  id: 'where',
  title: 'Where is P(μ)?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const points = threePoints(r);
    const mu1 = r.pick([0.2, 0.3, 0.4, 0.6, 0.7, 0.8]);
    const mu = r.pick([0.3, 0.5, 0.7].filter((v) => v !== mu1));
    const answer = clean(at(points, mu1, mu));
    // Step 0 draws the points alone; the panel's P(μ₁) is P₁, not the answer.
    const state = { ...defaults, points, mu: mu1, step: 0 };
    const [from, to] = mu < mu1 ? ['P₀', 'P₁'] : ['P₁', 'P₂'];
    const hint = `μ = ${mu} comes ${mu < mu1 ? 'before' : 'after'} μ₁ = ${mu1}, so P(${mu}) lies on the curve between ${from} and ${to}; for the exact place, solve equations 2 and 3 for a₀, a₁, a₂ and take P(μ) = a₂μ² + a₁μ + a₀.`;
    return {
      state,
      prompt: `${passes(points, mu1)}. Where is P(${mu})?`,
      task: pointTask('quadratic', answer, GUESS_TOLERANCE, hint),
      // The dots at equal steps of μ (step 3 on) include the one asked for.
      working: { ...state, step: LAST_STEP },
    };
  },
};

const compute: ExerciseSpec<QuadraticState> = {
  id: 'compute',
  title: 'Compute P(μ) from equations 2 and 3',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const points = threePoints(r);
    const mu1 = 0.5;
    const mu = r.pick([0.2, 0.3, 0.7, 0.8]);
    const answer = clean(at(points, mu1, mu));
    const [p0, p1, p2] = points;
    const [, , a2] = parametricQuadratic(p0, p1, p2, mu1);
    const shifted = (by: readonly number[]) => clean(answer.map((v, d) => v + by[d]));
    const mistakes = [
      {
        // a2 with the wrong sign changes a1 = P2 − P0 − a2 by 2a2: P(μ) moves by 2a2(μ − μ²).
        values: shifted(a2.map((v) => -2 * v * (mu * mu - mu))),
        hint: 'Check the sign of a₂: solving equations 2 and 3 divides by μ₁(μ₁ − 1) = −0.25, a negative number.',
      },
      {
        values: clean(at(points, mu1, 1 - mu)),
        hint: `That is P(${words(1 - mu)}): μ = 0 is at P₀ and μ = 1 at P₂, so take μ = ${mu} itself.`,
      },
      {
        values: shifted(p0.map((v) => -v)),
        hint: 'Add a₀ = P₀: P(μ) = a₂μ² + a₁μ + a₀.',
      },
      {
        values: shifted(a2.map((v) => v * mu)),
        hint: 'Equation 2 gives a₁ = P₂ − P₀ − a₂: subtract a₂ when you work out a₁.',
      },
      {
        values: clean(mu < 0.5 ? pointBetween(p0, p1, 2 * mu) : pointBetween(p1, p2, 2 * mu - 1)),
        hint: 'That point is on the straight polygon P₀P₁P₂: the curve bends away from it, which a₂μ² adds.',
      },
    ];
    const hint =
      'Work through equations 2 and 3 again: a₀ = P₀, a₂ = (P₁ − P₀ − μ₁(P₂ − P₀)) / (μ₁(μ₁ − 1)), a₁ = P₂ − P₀ − a₂, then P(μ) = a₂μ² + a₁μ + a₀.';
    const state = { ...defaults, points, mu: mu1, step: 0 };
    return {
      state,
      prompt: `${passes(points, mu1)}. Compute P(${mu}) to 2 decimals (within 0.01).`,
      task: {
        kind: 'number',
        fields: ['x', 'y'],
        tolerance: 0.01,
        answer,
        check: (values) => checkNumbers(values, answer, 0.01, hint, mistakes),
      },
      // Step 2 writes a₀, a₁, a₂ with their numbers; step 3 draws the dot at μ.
      working: { ...state, step: LAST_STEP },
    };
  },
};

const steer: ExerciseSpec<QuadraticState> = {
  id: 'steer',
  title: 'Steer a dot of equal μ with P₁',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const { goal, points } = steerPoints(r);
    const mu1 = 0.5;
    const mu = r.pick([0.2, 0.3, 0.7, 0.8]);
    // P1 starts √2 or more from where it should be: P(μ) is then 0.64√2 ≈ 0.9 or more from the target.
    const target = at(goal, mu1, mu).map((v) => Math.round(v * 100) / 100);
    // How far P(μ) moves when P1 moves one unit: P1's weight at μ.
    const weight = parametricQuadraticPoint([0], [1], [0], mu1, mu)[0];
    const state = { ...defaults, points, mu: mu1, step: TICKS_STEP };
    const check = (s: QuadraticState) => {
      if (s.mu !== mu1)
        return { correct: false, message: `Put μ₁ back at ${mu1}: the question moves P₁ only.` };
      for (const k of [0, 2]) {
        if (distance(s.points[k], points[k]) > 1e-9)
          return {
            correct: false,
            message: `Move only P₁: put P${k === 0 ? '₀' : '₂'} back at ${pointWords(points[k])}.`,
          };
      }
      const dot = at(s.points, mu1, mu);
      const off = distance(dot, target);
      const there = `P(${mu}) is at ${pointWords(dot)}, ${words(off)} from ${pointWords(target)}`;
      return off <= STEER_TOLERANCE
        ? { correct: true, message: `Correct: ${there}.` }
        : {
            correct: false,
            message: `${there}. It moves ${words(weight)} times as far as P₁ does (P₁’s weight at μ = ${mu}).`,
          };
    };
    const solution = { ...state, points: goal };
    return {
      state,
      prompt: `With μ₁ = 0.5, drag P₁ until the dot for μ = ${mu} sits at ${pointWords(target)}, within ${STEER_TOLERANCE}.`,
      task: { kind: 'construct', check, solution },
      working: { ...solution, step: LAST_STEP },
      marks: [{ figure: 'quadratic', at: target, label: 'target' }],
    };
  },
};

/** The quadratic lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<QuadraticState>[] = [where, compute, steer];
