import {
  type ExerciseSpec,
  type Posed,
  type Random,
  type Verdict,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { pointWords, sub, words } from '../../kit/format';
import { distance, lagrangeBasis, lagrangePoint, parameterValues, type Point } from '../../math';
import { derive } from './model';
import { interpolation } from './script';
import type { LagrangeState } from './state';

// The lesson's practice, on five points at tₖ = 0, 0.25, 0.5, 0.75, 1: where
// P(t) is between the nodes, one weight Lₖ(t) worked out, and one point
// dragged to steer P(t), against its weight when that weight is negative.

/** The nodes of five equally spaced points. */
const NODES = parameterValues([[0], [1], [2], [3], [4]], 0);
/** Between the nodes (at a node P(t) is a point itself). */
const OFF_NODES = [0.1, 0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9];
/** How far a guessed point may be from P(t): about 3% of the figure (some 7 units across). */
export const GUESS_TOLERANCE = 0.2;
/** How close the steered P(t) must come: about 1.5% of the figure, a finger's reach. */
export const STEER_TOLERANCE = 0.1;

/** Printed digits only: 0.37440000000000007 is shown, and checked, as 0.3744. */
const clean = (v: number) => Number(v.toPrecision(12));
const nodesWords = NODES.join(', ');

/**
 * Five integer points from x = 0 to 6, in order, not all at one height (so
 * never on one line), each at height 0 to 3.
 */
export function fivePoints(r: Random): Point[] {
  const xs = [0, r.int(1, 2), 3, r.int(4, 5), 6];
  for (;;) {
    const ys = xs.map(() => r.int(0, 3));
    if (ys.some((y) => y !== ys[0])) return xs.map((x, k) => [x, ys[k]]);
  }
}

/** The exercise's figure: the five points, equally spaced tₖ, no spline, at step `step`. */
const setUp = (defaults: LagrangeState, points: Point[], t: number, step: number) => ({
  ...defaults,
  points,
  t,
  spacing: 'uniform' as const,
  spline: false,
  step,
});
/** The script's last step: the polynomial, with P(t) drawn and written. */
const lastStep = (s: LagrangeState) => interpolation.lastStep(s);
/** On the curve's figure as it opens: the model's own frame, which a wild polynomial leaves. */
const onFigure = (s: LagrangeState, p: readonly number[]) => {
  const { minX, maxX, minY, maxY } = derive(s, interpolation.shown(s, s.step)).curveBounds;
  return p[0] >= minX && p[0] <= maxX && p[1] >= minY && p[1] <= maxY;
};

const where: ExerciseSpec<LagrangeState> = {
  id: 'where',
  title: 'Where is P(t)?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    // Step 0 draws the points alone; at t = 0 the panel's P(t) is P₀, not the answer.
    let state: LagrangeState;
    let within: number[];
    do {
      state = setUp(defaults, fivePoints(r), 0, 0);
      const s = state;
      within = OFF_NODES.filter((t) => onFigure(s, lagrangePoint(NODES, s.points, t)));
    } while (within.length === 0);
    const { points } = state;
    const t = r.pick(within);
    const answer = lagrangePoint(NODES, points, t).map(clean);
    const k = NODES.findIndex((node) => node > t);
    const hint = `t = ${t} lies between t${sub(k - 1)} = ${NODES[k - 1]} and t${sub(k)} = ${NODES[k]}, but the curve need not stay between P${sub(k - 1)} and P${sub(k)}: work out the five weights Lₖ(${t}) (they add up to 1, and some are negative), then P(${t}) = Σ Lₖ(${t}) Pₖ.`;
    return {
      state,
      prompt: `The polynomial passes P₀ … P₄ at t = ${nodesWords}. Where is P(${t})?`,
      task: pointTask('curve', answer, GUESS_TOLERANCE, hint),
      // Each Lₖ(t) in turn, then the polynomial with P(t) drawn on it.
      working: { ...state, t, step: lastStep(state) },
    };
  },
};

/** Lₖ(t) = Π over j ≠ k of (t − tⱼ)/(tₖ − tⱼ), on nodes of one's choosing (for the slips). */
const basisOn = (nodes: readonly number[], k: number, t: number) => lagrangeBasis(nodes, t)[k];

const weight: ExerciseSpec<LagrangeState> = {
  id: 'weight',
  title: 'Work out a weight Lₖ(t)',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const points = fivePoints(r);
    const k = r.int(0, 4);
    const t = r.pick(OFF_NODES);
    const value = basisOn(NODES, k, t);
    const answer = [clean(value)];
    const name = (i: number) => `L${sub(i)}(${t})`;
    const neighbours = [k - 1, k + 1].filter((i) => i >= 0 && i <= 4);
    const mistakes = [
      {
        values: [clean(1 / value)],
        hint: `Each factor is (t − tⱼ)/(t${sub(k)} − tⱼ): t = ${t} goes on top and t${sub(k)} = ${NODES[k]} below; you have them upside down.`,
      },
      ...neighbours.map((i) => ({
        values: [clean(basisOn(NODES, i, t))],
        hint: `That is ${name(i)}: L${sub(k)} is the one that is 1 at its own node t${sub(k)} = ${NODES[k]}.`,
      })),
      {
        values: [clean(-value)],
        hint: `Check the sign: count the factors whose t − tⱼ is negative and those whose t${sub(k)} − tⱼ is.`,
      },
      {
        // The nodes taken as 0, 1, 2, 3, 4 while t stays between 0 and 1.
        values: [clean(basisOn([0, 1, 2, 3, 4], k, t))],
        hint: `The nodes are tⱼ = j/4 = ${nodesWords}, on the same scale as t = ${t}; not 0, 1, 2, 3, 4.`,
      },
    ];
    const hint = `Work through the product again: ${name(k)} = Π over j ≠ ${k} of (${t} − tⱼ)/(t${sub(k)} − tⱼ), four factors, one for each other node.`;
    // At t = 0 the panel's weights are 1 and 0s; step 0 plots no Lₖ yet.
    const state = setUp(defaults, points, 0, 0);
    return {
      state,
      prompt: `The five points have tₖ = ${nodesWords}. Compute ${name(k)} to 3 decimals (within 0.001).`,
      task: {
        kind: 'number',
        fields: [name(k)],
        tolerance: 0.001,
        answer,
        check: (values) => checkNumbers(values, answer, 0.001, hint, mistakes),
      },
      // Step k + 1 plots Lₖ and writes its value at t; the last step lists all five.
      working: { ...state, t, step: lastStep(state) },
    };
  },
};

/** Where P(t) is steered from: point k and t with |Lₖ(t)| ≥ 0.15, so a drag visibly moves it. */
const STEERS = OFF_NODES.flatMap((t) =>
  lagrangeBasis(NODES, t)
    .map((w, k) => ({ k, t, w }))
    .filter(({ w }) => Math.abs(w) >= 0.15),
);

const steer: ExerciseSpec<LagrangeState> = {
  id: 'steer',
  title: 'Steer P(t) with one point',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    for (;;) {
      const goal = fivePoints(r);
      const { k, t, w } = r.pick(STEERS);
      // Pₖ opens two units higher or lower (P(t) is then 2|Lₖ(t)| ≥ 0.3 from the target), away
      // from the others where it is the highest or the lowest, so its goal is on the figure.
      const others = goal.filter((_, i) => i !== k).map((p) => p[1]);
      const y = goal[k][1];
      const dy = y > Math.max(...others) ? 2 : y < Math.min(...others) ? -2 : r.pick([-2, 2]);
      const points = goal.map((p, i): Point => (i === k ? [p[0], p[1] + dy] : p));
      const target = lagrangePoint(NODES, goal, t).map((v) => Math.round(v * 100) / 100);
      // Opened at the last step: the polynomial with the dot P(t) on it.
      const base = setUp(defaults, points, t, 0);
      const opened = { ...base, step: lastStep(base) };
      if (onFigure(opened, target)) return steerAt(opened, goal, { k, t, w }, target);
    }
  },
};

/** The steering exercise, from the figure it opens with, the goal, Pₖ, t, Lₖ(t) and the target. */
function steerAt(
  opened: LagrangeState,
  goal: Point[],
  { k, t, w }: (typeof STEERS)[number],
  target: number[],
): Posed<LagrangeState> {
  const points = opened.points;
  const name = `P${sub(k)}`;
  const check = (s: LagrangeState): Verdict => {
    if (s.points.length !== 5)
      return { correct: false, message: `Keep the five points: this question moves ${name} only.` };
    if (s.spacing !== 'uniform')
      return {
        correct: false,
        message: `Choose equally spaced tₖ again: the target was worked out with tₖ = ${nodesWords}.`,
      };
    if (s.t !== t) return { correct: false, message: `Put t back at ${t}: the dot is P(${t}).` };
    const moved = s.points.findIndex((p, i) => i !== k && distance(p, points[i]) > 1e-9);
    if (moved !== -1)
      return {
        correct: false,
        message: `Move only ${name}: put P${sub(moved)} back at ${pointWords(points[moved])}.`,
      };
    const dot = lagrangePoint(NODES, s.points, t);
    const gap = distance(dot, target);
    const there = `P(${t}) is at ${pointWords(dot)}, ${words(gap)} from ${pointWords(target)}`;
    if (gap <= STEER_TOLERANCE) return { correct: true, message: `Correct: ${there}.` };
    const way = w < 0 ? 'the opposite way' : 'the same way';
    return {
      correct: false,
      message: `${there}. L${sub(k)}(${t}) = ${words(w)}: P(${t}) moves ${words(Math.abs(w))} times as far as ${name}, ${way}.`,
    };
  };
  return {
    state: opened,
    prompt: `Drag ${name} alone until the dot P(${t}) sits at ${pointWords(target)}, within ${STEER_TOLERANCE}.`,
    // The goal's P(t) is the target to rounding (under 0.01).
    task: { kind: 'construct', check, solution: { ...opened, points: goal } },
    working: { ...opened, points: goal },
    marks: [{ figure: 'curve', at: target, label: 'target' }],
  };
}

/** The Lagrange lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<LagrangeState>[] = [where, weight, steer];
