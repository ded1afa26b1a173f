import { script, step } from '../../kit/script';
import type { CurvatureModel } from './model';
import type { CurvatureState } from './state';
import { list, parameter, point, unit, value } from './tex';

/** What the steps of the space curve reveal, by name. */
export type SpaceReveal =
  'curve' | 'tangent' | 'normal' | 'binormal' | 'osculating' | 'frames' | 'flips';

const at = (m: CurvatureModel) => m.space.at;
const helix = (s: CurvatureState) => s.spaceCurve === 'helix';
/** Where P′ × P″ = 0 there is no N, B or τ. */
const undefinedFrame = (m: CurvatureModel) => {
  const t = parameter(at(m).t);
  return `P'(${t}) \\times P''(${t}) = 0:\\ N,\\ B,\\ \\tau\\ \\text{undefined}`;
};

/** What the frame does along the whole curve: flips where κ nearly vanishes, never flips, or is undefined where κ = 0. */
type Along = 'flips' | 'steady' | 'straight';

function along(m: CurvatureModel): Along {
  const { flips, least } = m.space;
  if (flips.length) return 'flips';
  // κ so small it reads 0 is no longer "above 0".
  return least !== null && least > 0 && value(least) !== value(0) ? 'steady' : 'straight';
}

const FLIP_CAPTIONS: Record<Along, (helix: boolean) => string> = {
  flips: () => 'Where κ → 0 the frame flips: N and B swing round fast (at κ = 0 they would jump)',
  steady: (isHelix) =>
    isHelix
      ? 'κ = a/(a² + b²) never falls to 0: the frame turns steadily and never flips'
      : 'κ stays above 0 all along, so the frame never flips: it turns smoothly',
  straight: () => 'κ falls to 0 on this curve: there N and B are undefined',
};

/**
 * The Frenet frame of a space curve, one vector at a time, then the
 * osculating plane, the frame carried along, and whether it flips.
 */
export const spaceScript = script<CurvatureState, CurvatureModel, SpaceReveal>(
  step('curve', 'The curve in space and the point P(t)', ({ state, model }) => {
    const { t, point: p } = at(model);
    return helix(state)
      ? `P(${parameter(t)}) = (a\\cos\\theta,\\ a\\sin\\theta,\\ b\\theta) = ${point(p)},\\ \\theta = 4\\pi t`
      : `P(${parameter(t)}) = ${point(p)}`;
  }),
  step('tangent', 'The unit tangent T = P′/|P′|', ({ model }) => {
    const { tangent } = at(model);
    return tangent ? `T = \\frac{P'}{|P'|} = ${unit(tangent)}` : `P' = 0:\\ T\\ \\text{undefined}`;
  }),
  step(
    'normal',
    'The principal normal N, towards which T turns; κ = |P′ × P″|/|P′|³',
    ({ model }) => {
      const { normal, curvature } = at(model);
      if (!normal || curvature === null) return undefinedFrame(model);
      const general = `\\kappa = \\frac{|P' \\times P''|}{|P'|^3} = ${value(curvature)}`;
      const closed = model.space.closed;
      return closed
        ? `${general},\\quad \\frac{a}{a^2+b^2} = ${value(closed.curvature)},\\quad N = ${unit(normal)}`
        : `${general},\\quad N = ${unit(normal)}`;
    },
  ),
  step('binormal', 'The binormal B = T × N; the torsion τ says how fast B turns', ({ model }) => {
    const { binormal, torsion } = at(model);
    if (!binormal || torsion === null) return undefinedFrame(model);
    const general = `\\tau = \\frac{(P' \\times P'') \\cdot P'''}{|P' \\times P''|^2} = ${value(torsion)}`;
    const closed = model.space.closed;
    return closed
      ? `B = T \\times N = ${unit(binormal)},\\quad ${general},\\quad \\frac{b}{a^2+b^2} = ${value(closed.torsion)}`
      : `B = T \\times N = ${unit(binormal)},\\quad ${general}`;
  }),
  step(
    'osculating',
    'The osculating plane spanned by T and N, with the osculating circle',
    ({ model }) => {
      const { curvature } = at(model);
      return curvature
        ? `\\text{plane: } P + \\alpha T + \\beta N,\\quad R = \\frac{1}{\\kappa} = ${value(1 / curvature)}`
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
    ({ state, model }) => FLIP_CAPTIONS[along(model)](helix(state)),
    ({ state, model }) => {
      const { flips, least } = model.space;
      switch (along(model)) {
        case 'flips':
          return `\\kappa \\to 0\\ \\text{near}\\ t = ${list(flips)}:\\ N = \\frac{dT/ds}{|dT/ds|}\\ \\text{turns over}`;
        case 'steady':
          return helix(state)
            ? `\\kappa = a/(a^2+b^2) = ${value(least!)} > 0\\ \\text{for every}\\ t:\\ N = -(\\cos\\theta,\\ \\sin\\theta,\\ 0)\\ \\text{never flips}`
            : `\\min_t \\kappa = ${value(least!)} > 0:\\ \\text{the frame never flips}`;
        case 'straight':
          return `\\min_t \\kappa = 0:\\ N,\\ B\\ \\text{undefined where}\\ \\kappa = 0`;
      }
    },
  ),
);
