import { type ExerciseSpec, type Mistake, checkNumbers, random } from '../../kit/exercise';
import { sub, words } from '../../kit/format';
import { splitBezier } from '../../math';
import { FRIENDLY_T, arch, listText, polygonOnly, walked } from './exerciseSetup';
import type { DeCasteljauState } from './state';

// Subdivision by hand: a control point of one half of the curve split at t,
// read off the construction's levels.

/** The two halves of the split at t, each from one end to P(t): the first and the last point of each level. */
const HALVES = [
  { name: 'left', from: 'P₀ to P(t)', points: ['P₀,₀', 'P₁,₀', 'P₂,₀', 'P₃,₀'] },
  { name: 'right', from: 'P(t) to P₃', points: ['P₃,₀', 'P₂,₁', 'P₁,₂', 'P₀,₃'] },
] as const;
const ORDINALS = ['first', 'second', 'third', 'fourth'];

/** Subdivision: the control points of one half come from the construction's levels. */
export const splitHalf: ExerciseSpec<DeCasteljauState> = {
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
