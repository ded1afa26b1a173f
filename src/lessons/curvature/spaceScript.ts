import { script, step } from '../../kit/script';
import type { CurvatureModel } from './model';
import type { CurvatureState } from './state';
import { list, tex, vec } from './tex';

/** What the steps of the space curve reveal, by name. */
export type SpaceReveal =
  'curve' | 'tangent' | 'normal' | 'binormal' | 'osculating' | 'frames' | 'flips';

const at = (m: CurvatureModel) => m.space.at;
const helix = (s: CurvatureState) => s.spaceCurve === 'helix';
/** Where P′ × P″ = 0 there is no N, B or τ. */
const undefinedFrame = (m: CurvatureModel) => {
  const t = tex(at(m).t);
  return `P'(${t}) \\times P''(${t}) = 0:\\ N,\\ B,\\ \\tau\\ \\text{undefined}`;
};

/**
 * The Frenet frame of a space curve, one vector at a time, then the
 * osculating plane, the frame carried along, and where it flips.
 */
export const spaceScript = script<CurvatureState, CurvatureModel, SpaceReveal>(
  step('curve', 'The curve in space and the point P(t)', ({ state, model }) => {
    const { t, point } = at(model);
    return helix(state)
      ? `P(${tex(t)}) = (a\\cos\\theta,\\ a\\sin\\theta,\\ b\\theta) = ${vec(point)},\\ \\theta = 4\\pi t`
      : `P(${tex(t)}) = ${vec(point)}`;
  }),
  step('tangent', 'The unit tangent T = P′/|P′|', ({ model }) => {
    const { tangent } = at(model);
    return tangent ? `T = \\frac{P'}{|P'|} = ${vec(tangent)}` : `P' = 0:\\ T\\ \\text{undefined}`;
  }),
  step(
    'normal',
    'The principal normal N, towards which T turns; κ = |P′ × P″|/|P′|³',
    ({ state, model }) => {
      const { normal, curvature } = at(model);
      if (!normal || curvature === null) return undefinedFrame(model);
      return helix(state)
        ? `\\kappa = \\frac{|P' \\times P''|}{|P'|^3} = ${tex(curvature, 10)} = \\frac{a}{a^2+b^2},\\quad N = ${vec(normal)}`
        : `\\kappa = \\frac{|P' \\times P''|}{|P'|^3} = ${tex(curvature)},\\quad N = ${vec(normal)}`;
    },
  ),
  step(
    'binormal',
    'The binormal B = T × N; the torsion τ says how fast B turns',
    ({ state, model }) => {
      const { binormal, torsion } = at(model);
      if (!binormal || torsion === null) return undefinedFrame(model);
      return helix(state)
        ? `B = T \\times N = ${vec(binormal)},\\ \\tau = ${tex(torsion, 10)} = \\frac{b}{a^2+b^2}`
        : `B = T \\times N = ${vec(binormal)},\\quad \\tau = \\frac{(P' \\times P'') \\cdot P'''}{|P' \\times P''|^2} = ${tex(torsion)}`;
    },
  ),
  step(
    'osculating',
    'The osculating plane spanned by T and N, with the osculating circle',
    ({ model }) => {
      const { curvature } = at(model);
      return curvature
        ? `\\text{plane: } P + \\alpha T + \\beta N,\\quad R = \\frac{1}{\\kappa} = ${tex(1 / curvature)}`
        : undefinedFrame(model);
    },
  ),
  step(
    'frames',
    'The frame carried along the curve',
    () =>
      `\\frac{dT}{ds} = \\kappa N,\\quad \\frac{dN}{ds} = -\\kappa T + \\tau B,\\quad \\frac{dB}{ds} = -\\tau N`,
  ),
  step(
    'flips',
    'Where κ → 0 the frame flips: N and B swing round fast (at κ = 0 they would jump)',
    ({ model }) =>
      model.space.flips.length
        ? `\\kappa \\to 0\\ \\text{near}\\ t = ${list(model.space.flips)}:\\ N = \\frac{dT/ds}{|dT/ds|}\\ \\text{turns over}`
        : `\\kappa > 0\\ \\text{everywhere: the frame never flips}`,
  ),
);
