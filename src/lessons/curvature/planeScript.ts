import { script, step } from '../../kit/script';
import type { CurvatureModel } from './model';
import type { PlaneAt, PlaneModel } from './planeModel';
import type { CurvatureState } from './state';
import { list, parameter, point, unit, value } from './tex';

/** What the steps of the plane curve reveal, by name. */
export type PlaneReveal =
  'curve' | 'velocity' | 'tangent' | 'normal' | 'curvature' | 'comb' | 'inflections';

/** The way the curve turns at the cursor: the sign of κ (of x′y″ − y′x″), or why it turns neither way. */
export type Turn = 'left' | 'right' | 'straight' | 'stopped';

/** Left (anticlockwise) for κ > 0, right (clockwise) for κ < 0; straight at κ = 0, stopped where P′ = 0. */
export function turnOf(at: PlaneAt): Turn {
  if (at.curvature === null) return 'stopped';
  if (!at.normal) return 'straight';
  return at.curvature > 0 ? 'left' : 'right';
}

/**
 * The parameter the plane curve's formulas use: t on one piece; on several,
 * the global p̄ = pieces·t (the lecture slides' p̄), in which P′ is the piece's
 * own derivative dP/dp (the local p = p̄ − i).
 */
const pieced = (plane: PlaneModel) => plane.pieces.segments.length > 1;
const symbol = (plane: PlaneModel) => (pieced(plane) ? 'p̄' : 't');
const texSymbol = (plane: PlaneModel) => (pieced(plane) ? '\\bar p' : 't');
/** P(0.3) on one piece; P(p̄) on several, p̄ given in the first step's formula. */
const argument = (plane: PlaneModel) => (pieced(plane) ? '\\bar p' : parameter(plane.at.t));

/** κ = (x′y″ − y′x″)/|P′|³ with its numbers, or why it is undefined. */
function kappa(at: PlaneAt): string {
  if (at.curvature === null)
    return `\\kappa = \\frac{x'y'' - y'x''}{|P'|^3}\\ \\text{is undefined: } P' = 0`;
  const [v, a] = [at.velocity, at.acceleration];
  // At an inflection the model counts κ as 0 (a numerator of rounding size): it is written 0.
  const numerator = at.curvature === 0 ? '0' : value(v[0] * a[1] - v[1] * a[0]);
  const curvature = at.curvature === 0 ? '0' : value(at.curvature);
  return `\\kappa = \\frac{x'y'' - y'x''}{|P'|^3} = \\frac{${numerator}}{${value(at.speed ** 3)}} = ${curvature}`;
}

const plane = (m: CurvatureModel) => m.plane!;
const at = (m: CurvatureModel) => m.plane!.at;

const NORMAL_CAPTIONS: Record<Turn, string> = {
  left: 'The unit normal N: T turned a quarter turn anticlockwise, to the left, the way the curve turns',
  right:
    'The unit normal N: T turned a quarter turn clockwise, to the right, the way the curve turns',
  straight: 'The unit normal N is undefined here: κ = 0, the curve turns neither way',
  stopped: 'The unit normal N is undefined here: P′ = 0, so there is no tangent T to turn',
};

const NORMAL_FORMULAS: Record<Turn, (n: string) => string> = {
  left: (n) => `\\text{turning left: } N = (-T_y,\\ T_x) = ${n}`,
  right: (n) => `\\text{turning right: } N = (T_y,\\ -T_x) = ${n}`,
  straight: () => `\\kappa = 0:\\ N\\ \\text{is undefined}`,
  stopped: () => `P' = 0:\\ N\\ \\text{is undefined}`,
};

const CURVATURE_CAPTIONS: Record<Turn, string> = {
  left: 'The curvature κ and the osculating circle of radius 1/|κ|',
  right: 'The curvature κ and the osculating circle of radius 1/|κ|',
  straight:
    'The curvature κ = 0: the osculating circle’s radius 1/|κ| is infinite, so none is drawn',
  stopped: 'The curvature κ is undefined where P′ = 0: there is no osculating circle',
};

/**
 * The plane curve, as the lecture builds up its frame: P(t), the velocity,
 * T, N, κ with the osculating circle, the comb, and where N is undefined.
 * Each caption says what the figure shows at the cursor: which way N points
 * is the sign of κ there.
 */
export const planeScript = script<CurvatureState, CurvatureModel, PlaneReveal>(
  step(
    'curve',
    ({ model }) => `${plane(model).pieces.name} and the point P(t)`,
    ({ model }) => {
      const m = plane(model);
      const p = point(m.at.point);
      if (!pieced(m)) return `P(${parameter(m.at.t)}) = ${p}`;
      const { s, piece, u, t } = m.at;
      const pieces = m.pieces.segments.length;
      return `\\bar p = ${pieces} \\cdot ${parameter(t)} = ${parameter(s)}\\ (\\text{piece } ${piece},\\ p = ${parameter(u)}):\\quad P(\\bar p) = ${p}`;
    },
  ),
  step(
    'velocity',
    ({ model }) => {
      const x = symbol(plane(model));
      return `The velocity P′(${x}): its length |P′(${x})| is the speed`;
    },
    ({ model }) =>
      `P'(${argument(plane(model))}) = ${point(at(model).velocity)},\\quad |P'| = ${value(at(model).speed)}`,
  ),
  step('tangent', 'The unit tangent T = P′/|P′|', ({ model }) => {
    const { tangent } = at(model);
    return tangent
      ? `T = \\frac{P'}{|P'|} = ${unit(tangent)}`
      : `|P'(${argument(plane(model))})| = 0:\\ T = P'/|P'| = 0/0\\ \\text{is undefined}`;
  }),
  step(
    'normal',
    ({ model }) => NORMAL_CAPTIONS[turnOf(at(model))],
    ({ model }) => {
      const here = at(model);
      return NORMAL_FORMULAS[turnOf(here)](here.normal ? unit(here.normal) : '');
    },
  ),
  step(
    'curvature',
    ({ model }) => CURVATURE_CAPTIONS[turnOf(at(model))],
    ({ model }) => {
      const { circle } = at(model);
      return circle
        ? `${kappa(at(model))},\\quad R = \\frac{1}{|\\kappa|} = ${value(circle.radius)}`
        : kappa(at(model));
    },
  ),
  step(
    'comb',
    'The curvature comb: teeth in proportion to |κ|, on the outside of every bend',
    ({ model }) =>
      at(model).curvature === null
        ? kappa(at(model))
        : `\\text{tooth} = P - c\\,|\\kappa|\\,N,\\quad c = ${value(plane(model).combScale)},\\quad ${kappa(at(model))}`,
  ),
  step(
    'inflections',
    ({ model }) => {
      const { inflections, cusps } = plane(model);
      return inflections.length || cusps.length
        ? 'Where κ = 0 (an inflection) or the speed is 0 (a cusp), N is undefined'
        : 'No inflection (κ = 0) and no cusp (speed 0) on this curve: N is defined all along';
    },
    ({ model }) => {
      const m = plane(model);
      const x = texSymbol(m);
      const parts = [];
      if (m.inflections.length)
        parts.push(`\\kappa = 0\\ \\text{at}\\ ${x} = ${list(m.inflections)}`);
      if (m.cusps.length) parts.push(`P' = 0\\ \\text{at}\\ ${x} = ${list(m.cusps)}`);
      return parts.length
        ? parts.join(',\\quad ')
        : `\\kappa \\neq 0\\ \\text{and}\\ P' \\neq 0\\ \\text{for all}\\ ${x}`;
    },
  ),
);
