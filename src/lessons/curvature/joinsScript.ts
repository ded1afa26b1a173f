import { words } from '../../kit/format';
import { script, step } from '../../kit/script';
import type { Point } from '../../math';
import { type Sides, type SplineJoin, SLOPE_TOLERANCE, same } from './joinsModel';
import { SLOPE_STEP } from './curvatureSlope';
import type { CurvatureModel } from './model';
import type { CurvatureState } from './state';
import { point, value } from './tex';

/** What the steps of the joins reveal, by name. */
export type JoinsReveal = 'spline' | 'c2' | 'kappa' | 'slopes' | 'catmull' | 'g3';

/** At most this many joins are written out in a formula (the scene's spline has two). */
const WRITTEN = 3;

const natural = (m: CurvatureModel) => m.joins!.natural;
const catmull = (m: CurvatureModel) => m.joins!.catmullJoins;

/** Does κ have one value on both sides of the join (G²)? */
export const kappaContinuous = (j: SplineJoin) =>
  j.kappa !== null && same(j.kappa.before, j.kappa.after);
/** Does dκ/ds have one value on both sides of the join (with G², G³)? */
export const slopeContinuous = (j: SplineJoin) =>
  j.slope !== null && same(j.slope.before.perLength, j.slope.after.perLength, SLOPE_TOLERANCE);

/** "at each join", "at 1 of the 2 joins": how many joins a property fails at. */
function howMany(count: number, of: number): string {
  return count === of ? 'at each join' : `at ${count} of the ${of} joins`;
}

/** The first join where `fails`, with its two sides in words: "−6 → −5 at p̄ = 1". */
function firstJump(
  joins: readonly SplineJoin[],
  fails: (j: SplineJoin) => boolean,
  sides: (j: SplineJoin) => [number, number],
): string {
  const j = joins.find(fails)!;
  const [before, after] = sides(j);
  return `${words(before)} → ${words(after)} at p̄ = ${j.s}`;
}

/** One row per join (the first few): `row(j)` with its p̄ as `1^-` and `1^+`. */
function rows(joins: readonly SplineJoin[], row: (j: SplineJoin) => string): string {
  const shown = joins.slice(0, WRITTEN).map(row);
  if (joins.length > WRITTEN) shown.push('\\dots');
  return `\\begin{aligned}${shown.join('\\\\ ')}\\end{aligned}`;
}

const kappaSides = (j: SplineJoin): [number, number] => [j.kappa!.before, j.kappa!.after];
const slopeSides = (j: SplineJoin): [number, number] => [
  j.slope!.before.perLength,
  j.slope!.after.perLength,
];

/** κ at both sides of a join in TeX, = or ≠ as they are. */
function kappaRow(j: SplineJoin): string {
  if (!j.kappa) return `\\kappa(${j.s}) \\text{ is undefined: } P' = 0`;
  const relation = kappaContinuous(j) ? '=' : '\\ne';
  return `\\kappa(${j.s}^-) = ${value(j.kappa.before)} ${relation} \\kappa(${j.s}^+) = ${value(j.kappa.after)}`;
}

function slopeRow(j: SplineJoin): string {
  if (!j.slope) return `\\tfrac{d\\kappa}{ds}(${j.s}) \\text{ is undefined: } P' = 0`;
  const [before, after] = slopeSides(j);
  const relation = slopeContinuous(j) ? '=' : '\\ne';
  return `\\tfrac{d\\kappa}{ds}(${j.s}^-) = ${value(before)} ${relation} \\tfrac{d\\kappa}{ds}(${j.s}^+) = ${value(after)},\\ \\text{difference } ${value(after - before)}`;
}

const sameVector = (v: Sides<Point>) => v.before.every((x, d) => same(x, v.after[d]));

/** P′ and P″ the same on both sides: C². */
const derivativesContinuous = (j: SplineJoin) => sameVector(j.first) && sameVector(j.second);

/** P′ and P″ at both sides of a join: the C² of the natural spline, in numbers. */
function derivativesRow(j: SplineJoin): string {
  const side = (name: string, v: Sides<Point>) => {
    const equal = sameVector(v);
    return `${name}(${j.s}^-) = ${point(v.before)} ${equal ? '=' : '\\ne'} ${name}(${j.s}^+)${equal ? '' : ` = ${point(v.after)}`}`;
  };
  return `${side("P'", j.first)},\\quad ${side("P''", j.second)}`;
}

const NO_JOIN = 'The spline has one piece here: there is no join to look at';

/**
 * G², G³ and C^(n−1) at the joins of a spline (the continuation notes: car
 * surfaces need at least G³; splines of degree n can guarantee C^(n−1)): the
 * natural cubic spline, C² at its joins; κ continuous there (G²); the slope
 * of κ jumping (not G³); the Catmull-Rom spline of the same points, C¹, with κ
 * jumping (not G²); and what G³ would take.
 */
export const joinsScript = script<CurvatureState, CurvatureModel, JoinsReveal>(
  step(
    'spline',
    ({ model }) =>
      natural(model).length ? `${model.plane!.pieces.name}, joined at the dots` : NO_JOIN,
    ({ model }) => {
      const joins = natural(model);
      if (!joins.length) return `P(\\bar p)`;
      const at = joins.slice(0, WRITTEN).map((j) => `P(${j.s}) = ${point(j.point)}`);
      return `\\text{joins: }${at.join(',\\ ')}${joins.length > WRITTEN ? ',\\ \\dots' : ''}`;
    },
  ),
  step(
    'c2',
    ({ model }) => {
      const joins = natural(model);
      if (!joins.length) return NO_JOIN;
      return joins.every(derivativesContinuous)
        ? 'At each join P′ and P″ are the same on both sides: the spline is C²'
        : 'At some join P′ or P″ differs from one side to the other: not C² there';
    },
    ({ model }) => (natural(model).length ? rows(natural(model), derivativesRow) : 'C^2'),
  ),
  step(
    'kappa',
    ({ model }) => {
      const joins = natural(model);
      if (!joins.length) return NO_JOIN;
      const jumps = joins.filter((j) => !kappaContinuous(j));
      return jumps.length
        ? `κ against p̄ jumps ${howMany(jumps.length, joins.length)} (${firstJump(joins, (j) => !kappaContinuous(j), kappaSides)}): not G² there`
        : `κ against p̄ has one value on both sides of each join (${words(joins[0].kappa!.before)} at p̄ = ${joins[0].s}): the spline is G²`;
    },
    ({ model }) => (natural(model).length ? rows(natural(model), kappaRow) : '\\kappa'),
  ),
  step(
    'slopes',
    ({ model }) => {
      const joins = natural(model);
      if (!joins.length) return NO_JOIN;
      const kinks = joins.filter((j) => !slopeContinuous(j));
      return kinks.length
        ? `But the slope dκ/ds jumps ${howMany(kinks.length, joins.length)} (${firstJump(joins, (j) => !slopeContinuous(j), slopeSides)}): a kink in κ, so not G³`
        : 'The slope dκ/ds has one value on both sides of each join: no kink in κ here';
    },
    ({ model }) =>
      natural(model).length
        ? `${rows(natural(model), slopeRow)}\\qquad \\text{(one-sided differences of } \\kappa,\\ h = 10^{${Math.log10(SLOPE_STEP)}})`
        : '\\tfrac{d\\kappa}{ds}',
  ),
  step(
    'catmull',
    ({ model }) => {
      const joins = catmull(model);
      if (!joins.length) return 'Dashed: the Catmull-Rom spline of the same points, one piece';
      const c1 = model.joins!.catmull.pieces.joins.every((j) => j.continuity === 'C1');
      const jumps = joins.filter((j) => !kappaContinuous(j));
      const name = `Dashed: the Catmull-Rom spline of the same points${c1 ? ', only C¹' : ''}`;
      return jumps.length
        ? `${name}: κ jumps ${howMany(jumps.length, joins.length)} (${firstJump(joins, (j) => !kappaContinuous(j), kappaSides)}), so not G²`
        : `${name}: here κ has one value on both sides of each join`;
    },
    ({ model }) => (catmull(model).length ? rows(catmull(model), kappaRow) : '\\kappa'),
  ),
  step(
    'g3',
    'G³ needs dκ/ds continuous too: degree n gives Cⁿ⁻¹, so cubic pieces give C², and C³ takes degree 4 or more',
    () =>
      'G^3:\\ \\kappa \\text{ and } \\tfrac{d\\kappa}{ds} \\text{ continuous};\\qquad \\text{degree } n \\Rightarrow C^{n-1}:\\ n = 3 \\Rightarrow C^2,\\quad C^3 \\Rightarrow n \\ge 4',
  ),
);
