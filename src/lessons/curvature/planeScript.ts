import { script, step } from '../../kit/script';
import type { CurvatureModel } from './model';
import type { PlaneAt } from './planeModel';
import type { CurvatureState } from './state';
import { list, tex, vec } from './tex';

/** What the steps of the plane curve reveal, by name. */
export type PlaneReveal =
  'curve' | 'velocity' | 'tangent' | 'normal' | 'curvature' | 'comb' | 'inflections';

/** κ = (x′y″ − y′x″)/|P′|³ with its numbers, or why it is undefined. */
function kappa(at: PlaneAt): string {
  if (at.curvature === null)
    return `\\kappa = \\frac{x'y'' - y'x''}{|P'|^3} = \\frac{\\cdot}{0}\\ \\text{is undefined}`;
  const [v, a] = [at.velocity, at.acceleration];
  const numerator = v[0] * a[1] - v[1] * a[0];
  return `\\kappa = \\frac{x'y'' - y'x''}{|P'|^3} = \\frac{${tex(numerator)}}{${tex(at.speed ** 3)}} = ${tex(at.curvature)}`;
}

const at = (m: CurvatureModel) => m.plane!.at;

/**
 * The plane curve, as the lecture builds up its frame: P(t), the velocity,
 * T, N, κ with the osculating circle, the comb, and where N is undefined.
 */
export const planeScript = script<CurvatureState, CurvatureModel, PlaneReveal>(
  step(
    'curve',
    'The cubic Bézier curve and the point P(t)',
    ({ model }) => `P(${tex(at(model).t)}) = ${vec(at(model).point)}`,
  ),
  step(
    'velocity',
    'The velocity P′(t): its length |P′(t)| is the speed',
    ({ model }) =>
      `P'(${tex(at(model).t)}) = ${vec(at(model).velocity)},\\quad |P'| = ${tex(at(model).speed)}`,
  ),
  step('tangent', 'The unit tangent T = P′/|P′|', ({ model }) => {
    const { tangent, t } = at(model);
    return tangent
      ? `T = \\frac{P'}{|P'|} = ${vec(tangent)}`
      : `|P'(${tex(t)})| = 0:\\ T = \\tfrac{P'}{|P'|} = \\tfrac{0}{0}\\ \\text{is undefined}`;
  }),
  step('normal', 'The unit normal N: T turned a quarter turn anticlockwise', ({ model }) => {
    const { normal } = at(model);
    return normal
      ? `N \\perp T,\\ \\text{towards the turn: } N = ${vec(normal)}`
      : `\\kappa = 0\\ \\text{or}\\ P' = 0:\\ N\\ \\text{is undefined}`;
  }),
  step('curvature', 'The curvature κ and the osculating circle of radius 1/|κ|', ({ model }) => {
    const { circle } = at(model);
    return circle
      ? `${kappa(at(model))},\\quad R = \\frac{1}{|\\kappa|} = ${tex(circle.radius)}`
      : kappa(at(model));
  }),
  step(
    'comb',
    'The curvature comb: teeth as long as |κ|, on the outside of every bend',
    ({ model }) =>
      at(model).curvature === null
        ? kappa(at(model))
        : `\\text{tooth} = P - c\\,|\\kappa|\\,N,\\quad c = ${tex(model.plane!.combScale)},\\quad ${kappa(at(model))}`,
  ),
  step(
    'inflections',
    'Inflections (κ = 0) and cusps (speed 0): there N is undefined',
    ({ model }) => {
      const { inflections, cusps } = model.plane!;
      const parts = [];
      if (inflections.length) parts.push(`\\kappa = 0\\ \\text{at}\\ t = ${list(inflections)}`);
      if (cusps.length) parts.push(`P' = 0\\ \\text{at}\\ t = ${list(cusps)}`);
      return parts.length
        ? parts.join(',\\quad ')
        : `\\kappa \\neq 0\\ \\text{and}\\ P' \\neq 0\\ \\text{for all}\\ t`;
    },
  ),
);
