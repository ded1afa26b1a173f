/**
 * Exercises: a lesson's questions that the app checks. An exercise is posed
 * from a seed (kept in its link, so a lecturer can give everyone the same
 * numbers and each student's "New numbers" gives their own). Three kinds:
 * - `point`: guess where a point is (tap the figure, or type x and y);
 * - `number`: compute one or more numbers, checked to a stated tolerance;
 * - `construct`: move the figure's points until the maths says it holds.
 * A wrong answer gets a hint that names the step where it went wrong; "Show
 * me" opens the working (`working`) and walks its steps.
 */
import type { Point } from '../math';
import { words } from './format';

/** What a checker says of an answer. */
export interface Verdict {
  correct: boolean;
  /**
   * Plain words, read aloud to screen readers: on a right answer how close it
   * was; on a wrong one a hint naming the step where it went wrong.
   */
  message: string;
}

/** Numbers to compute, each typed into its own field. */
export interface NumberTask {
  kind: 'number';
  /** The label of each field, as the student reads it ("x", "y", "W(3,1,0.4)"). */
  fields: readonly string[];
  /** The largest error accepted in each number; the prompt says it. */
  tolerance: number;
  /** The right numbers, in field order (shown by "Show me"). */
  answer: readonly number[];
  check(values: readonly number[]): Verdict;
}

/** A point to guess, by a tap on a figure or by its coordinates. */
export interface PointTask {
  kind: 'point';
  /** The id of the figure the guess is placed on (its coordinates are the guess's). */
  figure: string;
  answer: Point;
  /** The largest distance accepted, in the figure's units. */
  tolerance: number;
  check(guess: Point): Verdict;
}

/** A figure to change (move points, set a slider) until the maths says it holds. */
export interface ConstructTask<S> {
  kind: 'construct';
  check(state: S): Verdict;
  /** A state that passes the check, for "Show me" and for the tests. */
  solution: S;
}

export type Task<S> = NumberTask | PointTask | ConstructTask<S>;

/** An exercise as posed for one seed. */
export interface Posed<S> {
  /** The figure as the exercise opens it (the answer not yet drawn). */
  state: S;
  /** The question in plain words and Unicode (P₁,₀, μ, ²), never TeX. */
  prompt: string;
  task: Task<S>;
  /** "Show me": the state whose steps show the working, walked from step 0 to its last. */
  working: S;
  /** The id of the scene the exercise is set in, where the state alone does not say. */
  scene?: string;
  /** Points the question names, marked on the figure (a target X to pass through). */
  marks?: readonly ExerciseMark[];
}

/** A point a question names, drawn on its figure with its label. */
export interface ExerciseMark {
  figure: string;
  at: Point;
  label: string;
}

export interface ExerciseSpec<S> {
  /** Stable id, in the link as `ex=<id>`. */
  id: string;
  /** Short title in the exercise list ("Where is P(t)?"). */
  title: string;
  kind: Task<S>['kind'];
  /** The exercise for this seed, from the lesson's default state. */
  pose(seed: number, defaults: S): Posed<S>;
}

/** A seeded random source (mulberry32): the same seed gives the same numbers everywhere. */
export interface Random {
  /** Uniform in [0, 1). */
  next(): number;
  /** A whole number in [min, max], both included. */
  int(min: number, max: number): number;
  /** One of the values. */
  pick<T>(values: readonly T[]): T;
}

export function random(seed: number): Random {
  let a = seed >>> 0;
  const next = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return {
    next,
    int: (min, max) => min + Math.floor(next() * (max - min + 1)),
    pick: (values) => values[Math.floor(next() * values.length)],
  };
}

/** The largest seed a link carries; new numbers are drawn in [1, MAX_SEED]. */
export const MAX_SEED = 999_999;

/** A new seed for "New numbers" (not the one shown now). */
export function newSeed(current: number, draw: () => number = Math.random): number {
  for (;;) {
    const seed = 1 + Math.floor(draw() * MAX_SEED);
    if (seed !== current) return seed;
  }
}

/** A mistake a student is likely to make: the numbers it gives, and the hint for it. */
export interface Mistake {
  values: readonly number[];
  hint: string;
}

/**
 * Checks typed numbers against the answer, each within the tolerance. A wrong
 * answer that matches a known mistake gets that mistake's hint; any other
 * gets `hint` (which should name the step to look at again).
 */
export function checkNumbers(
  values: readonly number[],
  answer: readonly number[],
  tolerance: number,
  hint: string,
  mistakes: readonly Mistake[] = [],
): Verdict {
  if (values.length !== answer.length || values.some((v) => !Number.isFinite(v)))
    return {
      correct: false,
      message: `Type ${answer.length === 1 ? 'a number' : 'every number'}.`,
    };
  const within = (given: readonly number[]) =>
    given.length === values.length && given.every((v, i) => Math.abs(values[i] - v) <= tolerance);
  if (within(answer)) {
    const off = Math.max(...values.map((v, i) => Math.abs(v - answer[i])));
    return {
      correct: true,
      message: off < 1e-9 ? 'Correct.' : `Correct (within ${words(off)} of the exact value).`,
    };
  }
  const mistake = mistakes.find((m) => within(m.values));
  return { correct: false, message: `Not yet. ${mistake ? mistake.hint : hint}` };
}

/**
 * The task of placing a guess for `answer` on `figure`: right within
 * `tolerance` (in the figure's units), and a wrong guess told how far off it
 * is, with `hint` (or the hint for that guess).
 */
export function pointTask(
  figure: string,
  answer: Point,
  tolerance: number,
  hint: string | ((guess: Point) => string),
): PointTask {
  return {
    kind: 'point',
    figure,
    answer,
    tolerance,
    check: (guess) =>
      checkPoint(guess, answer, tolerance, typeof hint === 'string' ? hint : hint(guess)),
  };
}

/** Checks a guessed point: within `tolerance` of the answer is right; either way says how far off. */
export function checkPoint(guess: Point, answer: Point, tolerance: number, hint: string): Verdict {
  if (!guess.every(Number.isFinite)) return { correct: false, message: 'Place a guess first.' };
  const off = Math.hypot(...answer.map((a, i) => (guess[i] ?? 0) - a));
  const where = `our guess is ${words(off)} from the point (${answer.map((a) => words(a)).join(', ')}).`;
  return off <= tolerance
    ? { correct: true, message: `Correct. Y${where}` }
    : { correct: false, message: `Not yet: y${where} ${hint}` };
}
