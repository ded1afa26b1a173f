import { filled, sub } from '../../kit/format';
import { type Revealed, type Script, repeat, script, step } from '../../kit/script';
import {
  basisFromColumns,
  basisOneLine,
  bezierBlend,
  bezierEnds,
  bezierExpanded,
  bezierGradients,
  bezierProduct,
  bothBlends,
  bothBlendsAt,
  conditions,
  conditionsMatrix,
  inverted,
} from './formulas';
import type { HermiteModel } from './model';
import { type HermiteState, patchCount } from './state';

/** What the steps reveal, by name: the figures and the panel ask for these. */
export type Reveal =
  | 'points'
  | 'gradients'
  | 'conditions'
  | 'matrix'
  | 'patch'
  | 'pointWeights'
  | 'gradientWeights'
  | 'pointAtMu'
  | 'bezier'
  | 'ends'
  | 'product'
  | 'expanded'
  | 'curve';

type HermiteScript = Script<HermiteState, HermiteModel, Reveal>;

/** "P₀ and P₁", "D₀ … D₄": the names of all the points or gradients, for a caption. */
const all = (letter: string, state: HermiteState) =>
  `${letter}₀ ${patchCount(state) === 1 ? 'and' : '…'} ${letter}${sub(patchCount(state))}`;

/** "from P₁ to P₂": the ends of patch i, for a caption. */
const ends = (i: number) => `from P${sub(i)} to P${sub(i + 1)}`;

/**
 * The lecture's construction of a spline from cubic patches (lecture notes,
 * "Spline Patches"): the points and their gradients, the four conditions on
 * a patch (equation 6), the same as a matrix, its inverse solving each patch
 * in turn (equation 7, one press per patch), the Hermite basis read down the
 * inverse's columns, and P(μ). Before the patches are solved, the conditions
 * and the matrix are about the chosen patch.
 */
export const construction = script<HermiteState, HermiteModel, Reveal>(
  step(
    'points',
    ({ state }) => `The points ${all('P', state)}: where the curve must pass`,
    () => 'P(\\mu) = a_3\\mu^3 + a_2\\mu^2 + a_1\\mu + a_0,\\quad P(0) = P_i,\\ P(1) = P_{i+1}',
  ),
  step(
    'gradients',
    ({ state }) =>
      state.mode === 'hand'
        ? `The gradients ${all('D', state)}, set by hand (arrows drawn a third as long)`
        : `The gradients ${all('D', state)} from the neighbours: Dₖ = (Pₖ₊₁ − Pₖ₋₁)/2, zero at both ends`,
    () => "P'(\\mu) = 3a_3\\mu^2 + 2a_2\\mu + a_1,\\quad P'(0) = D_i,\\ P'(1) = D_{i+1}",
  ),
  step(
    'conditions',
    ({ model: { patch } }) =>
      `Patch ${patch.index + 1}, ${ends(patch.index)}: its ends at μ = 0 and μ = 1 give four conditions on a₀ … a₃`,
    ({ model: { patch } }) => filled(conditions(patch.index, patch.data)),
  ),
  step(
    'matrix',
    ({ model: { patch } }) => {
      const [i, j] = [sub(patch.index), sub(patch.index + 1)];
      return `The four conditions as one matrix, the data in the order P${i}, D${i}, P${j}, D${j}`;
    },
    ({ model: { patch } }) => filled(conditionsMatrix(patch.index, patch.data)),
  ),
  // While the patches are built, the model's patch is the one this press solves.
  repeat(
    'patch',
    patchCount,
    ({ index, times }) =>
      `Patch ${index} of ${times}, ${ends(index - 1)}: the inverse matrix gives a₀ … a₃`,
    ({ model: { patch } }) => filled(inverted(patch.data, patch.coefficients)),
  ),
  step(
    'pointWeights',
    'Read down the columns of the inverse: H₀ and H₁ weight the end points, and H₀ + H₁ = 1',
    () => basisFromColumns([0, 1]),
  ),
  step(
    'gradientWeights',
    'H₂ and H₃ weight the end gradients: H₂ is never negative, H₃ never positive',
    () => basisFromColumns([2, 3]),
  ),
  step(
    'pointAtMu',
    ({ model: { patch } }) => {
      const [i, j] = [sub(patch.index), sub(patch.index + 1)];
      return `P(μ) on patch ${patch.index + 1}: H₀P${i} + H₁P${j} + H₂D${i} + H₃D${j}`;
    },
    ({ state, model: { patch } }) =>
      filled(basisOneLine(patch.index, state.mu, patch.weights, patch.point)),
  ),
);

/**
 * "Bézier curves are cubic spline patches" (lecture notes): a cubic Bézier
 * curve, its ends and its end gradients, which are a Hermite patch's data;
 * equation 7 times that data, and the curve multiplied out, give the same
 * a0 … a3; one curve, one point P(μ) either way. About the chosen patch.
 */
export const bezierScript = script<HermiteState, HermiteModel, Reveal>(
  step(
    'bezier',
    'A cubic Bézier curve: its control points B₀ … B₃ and their polygon',
    ({ model: { patch } }) => filled(bezierBlend(patch.bezier)),
  ),
  step(
    'ends',
    ({ model: { patch } }) =>
      `It starts at B₀ and ends at B₃: the patch's end points P${sub(patch.index)} and P${sub(patch.index + 1)}`,
    ({ model: { patch } }) => filled(bezierEnds(patch.index, patch.bezier)),
  ),
  step(
    'gradients',
    ({ model: { patch } }) => {
      const [i, j] = [sub(patch.index), sub(patch.index + 1)];
      return `The end legs are a third of the gradients: B₁ is the tip of D${i}'s arrow, B₂ is D${j}'s tip mirrored through P${j}`;
    },
    ({ model: { patch } }) => filled(bezierGradients(patch.index, patch.data)),
  ),
  step(
    'product',
    'The inverse matrix times B₀, 3(B₁ − B₀), B₃, 3(B₃ − B₂) gives a₀ … a₃',
    ({ model: { patch } }) => filled(bezierProduct(patch.data, patch.coefficients, true)),
  ),
  step(
    'expanded',
    'Multiplying out the Bézier curve gives the same a₀ … a₃',
    ({ model: { patch } }) => filled(bezierExpanded(patch.power)),
  ),
  step('curve', 'One cubic: the Bézier curve is the Hermite patch', ({ model: { patch } }) =>
    bothBlends(patch.index),
  ),
  step('pointAtMu', 'P(μ) from either blend is one point', ({ state, model: { patch } }) =>
    filled(bothBlendsAt(patch.index, state.mu, patch.bernsteinWeights, patch.weights, patch.point)),
  ),
);

/** The steps a state walks: the Bézier view has its own (the "bezier" scene's). */
export const scriptOf = (state: HermiteState): HermiteScript =>
  state.bezier ? bezierScript : construction;

/** What the state's step reveals, in its own script. */
export const shownAt = (state: HermiteState): Revealed<Reveal> =>
  scriptOf(state).shown(state, state.step);

/**
 * `after` (an edit of `before`) with its step: a script shown to its end stays
 * shown to its end (in the script `after` walks), else the step stays where it
 * was, within that script.
 */
export function keptAtEnd(before: HermiteState, after: HermiteState): HermiteState {
  const last = scriptOf(after).lastStep(after);
  const atEnd = before.step >= scriptOf(before).lastStep(before);
  return { ...after, step: atEnd ? last : Math.min(before.step, last) };
}
