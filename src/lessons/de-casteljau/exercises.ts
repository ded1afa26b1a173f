import {
  type ExerciseSpec,
  type Mistake,
  type Random,
  checkNumbers,
  checkPoint,
  random,
} from '../../kit/exercise';
import { pointWords, sub, words } from '../../kit/format';
import {
  type Point,
  bernstein,
  bezierPoint,
  deCasteljau,
  distance,
  splitBezier,
  subtract,
} from '../../math';
import { construction } from './script';
import type { DeCasteljauState } from './state';

/** Values of t a student can multiply by hand. */
const FRIENDLY_T = [0.2, 0.25, 0.3, 0.4, 0.6, 0.7, 0.75, 0.8];

/** "P₀ = (0, 1), P₁ = (2, 3), …": the control points, to work with by hand. */
const listText = (p: readonly Point[]) =>
  p.map((q, i) => `P${sub(i)} = ${pointWords(q)}`).join(', ');

/** P_{r,i} in Unicode, as the lesson's labels write it: P₂,₀. */
const levelName = (r: number, i: number) => `P${sub(r)},${sub(i)}`;

/**
 * A control polygon with integer corners that climbs and comes back down:
 * the ends are lower than every inner point, so the points are never on one
 * line and no two neighbours share a spot.
 */
export function arch(r: Random, degree: 2 | 3): Point[] {
  if (degree === 2)
    return [
      [0, r.int(0, 1)],
      [r.int(1, 4), r.int(3, 4)],
      [r.int(5, 6), r.int(0, 1)],
    ];
  return [
    [0, r.int(0, 1)],
    [r.int(0, 2), r.int(2, 4)],
    [r.int(3, 5), r.int(2, 4)],
    [r.int(5, 6), r.int(0, 1)],
  ];
}

/** The construction of these points at t, walked from the points to the curve. */
const walked = (defaults: DeCasteljauState, p: Point[], t: number): DeCasteljauState => {
  const s: DeCasteljauState = { ...defaults, p, t, mode: 'construction' };
  return { ...s, step: construction.lastStep(s) };
};

/** The control polygon only (step 1): no level cut yet, no P(t), no curve. */
const polygonOnly = (defaults: DeCasteljauState, p: Point[], t: number): DeCasteljauState => ({
  ...defaults,
  p,
  t,
  mode: 'construction',
  step: construction.stepOf({ ...defaults, p, t }, 'polygon'),
});

/** Predict P(t): guess where the construction's last point lands. */
const whereIsPoint: ExerciseSpec<DeCasteljauState> = {
  id: 'where-is-p',
  title: 'Where is P(t)?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const degree = r.pick([2, 3] as const);
    const p = arch(r, degree);
    const t = r.pick(FRIENDLY_T);
    const answer = bezierPoint(p, t);
    const tolerance = 0.2;
    const cuts = degree === 3 ? 'then once more' : 'then';
    return {
      state: polygonOnly(defaults, p, t),
      prompt: `Where is P(${words(t)}) on the Bézier curve of this control polygon? Tap your guess; within ${words(tolerance)} of the point counts.`,
      task: {
        kind: 'point',
        figure: 'construction',
        answer,
        tolerance,
        check: (guess) =>
          checkPoint(
            guess,
            answer,
            tolerance,
            `Level 1 cuts every edge at t = ${words(t)} from its first end, level 2 cuts the new edges, ${cuts}: the last point is P(t).`,
          ),
      },
      working: walked(defaults, p, t),
    };
  },
};

/** Compute one point of the construction by hand, P_{r,i} = (1 − t)·P_{r−1,i} + t·P_{r−1,i+1}. */
const levelPoint: ExerciseSpec<DeCasteljauState> = {
  id: 'level-point',
  title: 'A point of the construction',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const p = arch(r, 3);
    const t = r.pick(FRIENDLY_T);
    // Level 2 more often: it takes two cuts, so the slips have somewhere to happen.
    const level = r.pick([1, 2, 2]);
    const index = r.int(0, 3 - level);
    const levels = deCasteljau(p, t);
    const answer = levels[level][index];
    const name = levelName(level, index);
    const tolerance = 0.01;
    const mistakes: Mistake[] = [
      {
        values: deCasteljau(p, 1 - t)[level][index],
        hint: `Each cut weights its first point by 1 − t = ${words(1 - t)} and its second by t = ${words(t)}; you swapped t and 1 − t.`,
      },
      {
        values: deCasteljau(p, 0.5)[level][index],
        hint: `That cuts every edge in the middle; cut each one at t = ${words(t)} of the way from its first point.`,
      },
      ...[index - 1, index + 1]
        .filter((i) => i >= 0 && i <= 3 - level)
        .map((i) => ({
          values: levels[level][i],
          hint: `That is ${levelName(level, i)}, its neighbour on level ${level}: ${name} cuts the edge from ${levelName(level - 1, index)} to ${levelName(level - 1, index + 1)}.`,
        })),
      ...[index, index + 1].map((i) => ({
        values: levels[level - 1][i],
        hint: `That is ${levelName(level - 1, i)}, a point of level ${level - 1}: ${name} needs one more cut, of the edge from ${levelName(level - 1, index)} to ${levelName(level - 1, index + 1)}.`,
      })),
    ];
    const hint =
      level === 1
        ? `${name} = (1 − t)·P${sub(index)} + t·P${sub(index + 1)}: work out x and y of this one cut again.`
        : `First level 1: ${levelName(1, index)} and ${levelName(1, index + 1)}, each (1 − t)·Pᵢ + t·Pᵢ₊₁; then ${name} = (1 − t)·${levelName(1, index)} + t·${levelName(1, index + 1)}.`;
    return {
      state: polygonOnly(defaults, p, t),
      prompt: `For ${listText(p)} and t = ${words(t)}, compute the de Casteljau point ${name} (x and y, to 2 decimals).`,
      task: {
        kind: 'number',
        fields: [`${name} x`, `${name} y`],
        tolerance,
        answer,
        check: (values) => checkNumbers(values, answer, tolerance, hint, mistakes),
      },
      working: walked(defaults, p, t),
    };
  },
};

/** The two halves of the split at t, each from one end to P(t): the first and the last point of each level. */
const HALVES = [
  { name: 'left', from: 'P₀ to P(t)', points: ['P₀,₀', 'P₁,₀', 'P₂,₀', 'P₃,₀'] },
  { name: 'right', from: 'P(t) to P₃', points: ['P₃,₀', 'P₂,₁', 'P₁,₂', 'P₀,₃'] },
] as const;
const ORDINALS = ['first', 'second', 'third', 'fourth'];

/** Subdivision: the control points of one half come from the construction's levels. */
const splitHalf: ExerciseSpec<DeCasteljauState> = {
  id: 'split-half',
  title: 'Split the curve in two',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const p = arch(r, 3);
    const t = r.pick(FRIENDLY_T);
    const side = r.pick([0, 1] as const);
    const j = r.pick([1, 2]);
    const halves = splitBezier(p, t);
    const answer = halves[side][j];
    const half = HALVES[side];
    const other = HALVES[1 - side];
    const which = `the ${ORDINALS[j]} control point of the ${half.name} half`;
    const tolerance = 0.01;
    const mistakes: Mistake[] = [
      {
        values: halves[1 - side][j],
        hint: `That is the ${ORDINALS[j]} point of the ${other.name} half; the ${half.name} half runs from ${half.from}: ${half.points.join(', ')}.`,
      },
      {
        values: halves[side][3 - j],
        hint: `That counts from the wrong end: the ${half.name} half runs from ${half.from}, ${half.points.join(', ')} in that order.`,
      },
      {
        values: p[j],
        hint: `That is P${sub(j)} itself: each half has new control points, one from every level of the construction.`,
      },
      {
        values: splitBezier(p, 1 - t)[side][j],
        hint: `Each cut weights its first point by 1 − t = ${words(1 - t)} and its second by t = ${words(t)}; you swapped t and 1 − t.`,
      },
    ];
    const hint = `The ${half.name} half's control points are ${half.points.join(', ')}: this one is ${half.points[j]}, a point of level ${side === 0 ? j : 3 - j}; cut level by level at t = ${words(t)}.`;
    const working: DeCasteljauState = { ...walked(defaults, p, t), mode: 'halves' };
    return {
      state: polygonOnly(defaults, p, t),
      prompt: `Split the curve of ${listText(p)} at t = ${words(t)}: what is ${which}, from ${half.from}? Give x and y to 2 decimals.`,
      task: {
        kind: 'number',
        fields: ['x', 'y'],
        tolerance,
        answer,
        check: (values) => checkNumbers(values, answer, tolerance, hint, mistakes),
      },
      working,
    };
  },
};

/** P(t) lands on X, a shown distance from where it is now: far enough to need a real move. */
const TARGET_DISTANCES = [0.5, 0.6, 0.7];
const TARGET_DIRECTIONS = [0, 45, 90, 135, 180, 225, 270, 315];
/** How far Pₖ may end up outside the polygon's box, so a drag to it stays on the figure. */
const MARGIN = 0.3;

/** X and the polygon with Pₖ moved so that P(t) = X, for one direction and distance of X. */
function targetFor(p: readonly Point[], t: number, k: number, degrees: number, reach: number) {
  const now = bezierPoint(p, t);
  const angle = (degrees * Math.PI) / 180;
  // One decimal, so the student reads X off the grid.
  const target = [now[0] + reach * Math.cos(angle), now[1] + reach * Math.sin(angle)].map(
    (v) => Math.round(10 * v) / 10,
  );
  // P(t) moves by W(3, k, t) times Pₖ's move: Pₖ goes the gap divided by that weight.
  const weight = bernstein(3, k, t);
  const moved = p.map((q, i) => (i === k ? q.map((v, d) => v + (target[d] - now[d]) / weight) : q));
  return { target, moved, weight };
}

/** Inside the polygon's box, grown by MARGIN. */
const inBox = (p: readonly Point[], q: Point) =>
  [0, 1].every((d) => {
    const values = p.map((point) => point[d]);
    return q[d] >= Math.min(...values) - MARGIN && q[d] <= Math.max(...values) + MARGIN;
  });

/** Move one inner point until the curve passes through X at the given t. */
const throughPoint: ExerciseSpec<DeCasteljauState> = {
  id: 'through-point',
  title: 'Make the curve pass through X',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const p = arch(r, 3);
    const t = r.pick([0.4, 0.5, 0.6]);
    const k = r.pick([1, 2]);
    const candidates = TARGET_DIRECTIONS.flatMap((degrees) =>
      TARGET_DISTANCES.map((reach) => targetFor(p, t, k, degrees, reach)),
    );
    const fitting = candidates.filter(({ moved }) => inBox(p, moved[k]));
    const { target, moved, weight } = r.pick(fitting.length > 0 ? fitting : candidates);
    const tolerance = 0.08;
    const name = `P${sub(k)}`;
    const check = (state: DeCasteljauState) => {
      if (state.p.length !== 4)
        return {
          correct: false,
          message: `Keep the four control points P₀ … P₃ (there are ${state.p.length} now).`,
        };
      const strayed = state.p.findIndex((q, i) => i !== k && distance(q, p[i]) > 1e-9);
      if (strayed >= 0)
        return {
          correct: false,
          message: `Move only ${name}: P${sub(strayed)} belongs at ${pointWords(p[strayed])}.`,
        };
      const at = bezierPoint(state.p, t);
      const off = distance(at, target);
      const where = `P(${words(t)}) is at ${pointWords(at)}, ${words(off)} from X = ${pointWords(target)}`;
      if (off <= tolerance) return { correct: true, message: `Correct: ${where}.` };
      const needed = subtract(target, at).map((v) => v / weight);
      const slider =
        state.t === t
          ? ''
          : ` (the check reads t = ${words(t)}; the slider is at ${words(state.t)})`;
      return {
        correct: false,
        message: `Not yet: ${where}${slider}. P(${words(t)}) follows ${name} with the weight W(3, ${k}, ${words(t)}) = ${words(weight)}, so move ${name} by about ${pointWords(needed)}.`,
      };
    };
    return {
      state: walked(defaults, p, t),
      prompt: `Move only ${name} so that the curve passes through X = ${pointWords(target)} at t = ${words(t)}, within ${words(tolerance)}.`,
      task: { kind: 'construct', check, solution: walked(defaults, moved, t) },
      working: walked(defaults, moved, t),
      marks: [{ figure: 'construction', at: target, label: 'X' }],
    };
  },
};

/** The de Casteljau lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<DeCasteljauState>[] = [
  whereIsPoint,
  levelPoint,
  splitHalf,
  throughPoint,
];
