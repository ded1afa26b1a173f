import { texNumber, texResidue } from '../../kit/format';
import { narrow, script, step } from '../../kit/script';
import type { CircleModel, NurbsModel, ProjectiveModel } from './model';
import { n3, pt } from './notation';
import type { BSplineState } from './state';

/** What the steps of the NURBS weights scene reveal, by name. */
export type NurbsReveal = 'points' | 'plain' | 'weights' | 'sum';

/** A weight per control point: the plain B-spline first, then the weights and their sum. */
export const nurbsScript = script<BSplineState, NurbsModel, NurbsReveal>(
  step('points', 'The control points'),
  step('plain', 'All weights 1: the plain B-spline'),
  step(
    'weights',
    'Weights: a heavier point pulls the curve towards itself, a lighter one lets it go',
  ),
  narrow(
    step('sum', 'P(u) = Σ wᵢNᵢ(u)Pᵢ / Σ wᵢNᵢ(u), with the numbers at u', ({ model: m }) => {
      return `P(${n3(m.u)}) = \\dfrac{${weightedTerms(m).join(' + ')}}{${n3(m.rational.denominator)}} = ${pt(m.point)}`;
    }),
    // The sum over its denominator as a factor in front, its terms on as
    // many lines as a narrow box needs (a laptop's panel: 496 px in 404),
    // each term a group, so a line breaks after a +, never inside w·N.
    ({ model: m }) =>
      `P(${n3(m.u)}) = \\tfrac{1}{${n3(m.rational.denominator)}}\\bigl(${weightedTerms(m)
        .map((term) => `{${term}}`)
        .join(' + ')}\\bigr) = ${pt(m.point)}`,
  ),
);

/** The sum's terms wᵢ·Nᵢ(u) Pᵢ with their numbers, those of the points that count at u. */
const weightedTerms = (m: NurbsModel) =>
  m.basis.flatMap((b, i) =>
    b === 0 ? [] : [`${texNumber(m.weights[i], 2)}\\cdot${n3(b)}\\,P_{${i}}`],
  );

/** What the steps of the exact circle reveal, by name. */
export type CircleReveal = 'points' | 'weights' | 'arcs' | 'samples' | 'plain';

const circleGap = '\\max_u \\bigl\\lvert\\, \\lVert P(u) - c \\rVert - r \\,\\bigr\\rvert';

/** The exact circle: nine points with their weights, four rational arcs, checked against the circle. */
export const circleScript = script<BSplineState, CircleModel, CircleReveal>(
  step('points', 'Nine control points on a square'),
  step('weights', 'The polygon; weight 1 at the edge midpoints, √2/2 at the corners'),
  step('arcs', 'Four rational quadratic arcs, one per quarter'),
  step(
    'samples',
    'Sampled points of the curve lie on the circle, to rounding',
    ({ model: m }) => `${circleGap} = ${texResidue(m.circle.deviation)}`,
  ),
  step(
    'plain',
    'With every weight 1 instead: not a circle',
    ({ model: m }) => `\\text{all } w_i = 1:\\ ${circleGap} = ${n3(m.circle.plainDeviation)}`,
  ),
);

/** What the steps of the projective map reveal, by name. */
export type ProjectiveReveal = 'points' | 'curve' | 'map' | 'oldWeights';

/** The perspective map with the weights (the image of the curve), and without (not the image). */
export const projectiveScript = script<BSplineState, ProjectiveModel, ProjectiveReveal>(
  step('points', 'The control points'),
  step('curve', 'The NURBS curve'),
  step(
    'map',
    'A perspective map of the control points, each weight times its new w: the image of the curve',
    ({ model: { projective: pr } }) =>
      pr.error
        ? null
        : `w'_i = w_i\\,(h_{20}x_i + h_{21}y_i + h_{22}):\\ \\max_u \\lvert P_{HP}(u) - H(P(u)) \\rvert = ${texResidue(pr.deviation)}`,
  ),
  step(
    'oldWeights',
    'The same mapped points with their old weights: a different curve',
    ({ model: { projective: pr } }) =>
      pr.error
        ? null
        : `\\text{old weights } w_i:\\ \\max_u \\lvert P_{HP}(u) - H(P(u)) \\rvert = ${n3(pr.plainDeviation)}`,
  ),
);
