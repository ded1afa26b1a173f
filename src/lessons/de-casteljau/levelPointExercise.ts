import { type ExerciseSpec, type Mistake, checkNumbers, random } from '../../kit/exercise';
import { sub, words } from '../../kit/format';
import { deCasteljau } from '../../math';
import { FRIENDLY_T, arch, listText, polygonOnly, walked } from './exerciseSetup';
import type { DeCasteljauState } from './state';

// One point of the construction by hand, with the slips a student makes on
// the way (t and 1 − t swapped, the middle cut, a neighbour, a level too few).

/** P_{r,i} in Unicode, as the lesson's labels write it: P₂,₀. */
const levelName = (r: number, i: number) => `P${sub(r)},${sub(i)}`;

/** Compute one point of the construction by hand, P_{r,i} = (1 − t)·P_{r−1,i} + t·P_{r−1,i+1}. */
export const levelPoint: ExerciseSpec<DeCasteljauState> = {
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
