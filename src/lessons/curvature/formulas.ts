import type { Point } from '../../math';
import type { CurvatureModel } from './model';
import type { CurvatureState } from './state';

/** A number in TeX: four significant digits, a true minus sign. */
export const tex = (value: number, digits = 4) => {
  const text = Number(value.toPrecision(digits)).toString();
  return text.includes('e') ? value.toExponential(2).replace('e', '\\times 10^{') + '}' : text;
};
const vec = (v: Point) => `(${v.map((x) => tex(x)).join(',\\ ')})`;
const list = (ts: readonly number[]) => ts.map((t) => tex(t)).join(',\\ ');

/** The formula of the current step, with its numbers (presenter view shows it large). */
export function stepFormula(m: CurvatureModel, state: CurvatureState): string | null {
  if (state.part === 'plane') return planeFormula(m, state.step);
  if (state.part === 'space') return spaceFormula(m, state);
  return arcFormula(m, state);
}

function planeFormula(m: CurvatureModel, step: number): string | null {
  const plane = m.plane!;
  const at = plane.at;
  const t = tex(at.t);
  switch (step) {
    case 0:
      return `P(${t}) = ${vec(at.point)}`;
    case 1:
      return `P'(${t}) = ${vec(at.velocity)},\\quad |P'| = ${tex(at.speed)}`;
    case 2:
      return at.tangent
        ? `T = \\frac{P'}{|P'|} = ${vec(at.tangent)}`
        : `|P'(${t})| = 0:\\ T = \\tfrac{P'}{|P'|} = \\tfrac{0}{0}\\ \\text{is undefined}`;
    case 3:
      return at.normal
        ? `N \\perp T,\\ \\text{towards the turn: } N = ${vec(at.normal)}`
        : `\\kappa = 0\\ \\text{or}\\ P' = 0:\\ N\\ \\text{is undefined}`;
    case 4:
    case 5: {
      if (at.curvature === null)
        return `\\kappa = \\frac{x'y'' - y'x''}{|P'|^3} = \\frac{\\cdot}{0}\\ \\text{is undefined}`;
      const [v, a] = [at.velocity, at.acceleration];
      const numerator = v[0] * a[1] - v[1] * a[0];
      const kappa = `\\kappa = \\frac{x'y'' - y'x''}{|P'|^3} = \\frac{${tex(numerator)}}{${tex(at.speed ** 3)}} = ${tex(at.curvature)}`;
      if (step === 5)
        return `\\text{tooth} = P - c\\,|\\kappa|\\,N,\\quad c = ${tex(plane.combScale)},\\quad ${kappa}`;
      return at.circle
        ? `${kappa},\\quad R = \\frac{1}{|\\kappa|} = ${tex(at.circle.radius)}`
        : kappa;
    }
    default: {
      const parts = [];
      if (plane.inflections.length)
        parts.push(`\\kappa = 0\\ \\text{at}\\ t = ${list(plane.inflections)}`);
      if (plane.cusps.length) parts.push(`P' = 0\\ \\text{at}\\ t = ${list(plane.cusps)}`);
      return parts.length
        ? parts.join(',\\quad ')
        : `\\kappa \\neq 0\\ \\text{and}\\ P' \\neq 0\\ \\text{for all}\\ t`;
    }
  }
}

function spaceFormula(m: CurvatureModel, state: CurvatureState): string | null {
  const at = m.space.at;
  const t = tex(at.t);
  const helix = state.curve === 'helix';
  const undefinedFrame = `P'(${t}) \\times P''(${t}) = 0:\\ N,\\ B,\\ \\tau\\ \\text{undefined}`;
  switch (state.step) {
    case 0:
      return helix
        ? `P(${t}) = (a\\cos\\theta,\\ a\\sin\\theta,\\ b\\theta) = ${vec(at.point)},\\ \\theta = 4\\pi t`
        : `P(${t}) = ${vec(at.point)}`;
    case 1:
      return at.tangent
        ? `T = \\frac{P'}{|P'|} = ${vec(at.tangent)}`
        : `P' = 0:\\ T\\ \\text{undefined}`;
    case 2:
      if (!at.normal || at.curvature === null) return undefinedFrame;
      return helix
        ? `\\kappa = \\frac{|P' \\times P''|}{|P'|^3} = ${tex(at.curvature, 10)} = \\frac{a}{a^2+b^2},\\quad N = ${vec(at.normal)}`
        : `\\kappa = \\frac{|P' \\times P''|}{|P'|^3} = ${tex(at.curvature)},\\quad N = ${vec(at.normal)}`;
    case 3:
      if (!at.binormal || at.torsion === null) return undefinedFrame;
      return helix
        ? `B = T \\times N = ${vec(at.binormal)},\\ \\tau = ${tex(at.torsion, 10)} = \\frac{b}{a^2+b^2}`
        : `B = T \\times N = ${vec(at.binormal)},\\quad \\tau = \\frac{(P' \\times P'') \\cdot P'''}{|P' \\times P''|^2} = ${tex(at.torsion)}`;
    case 4:
      return at.curvature
        ? `\\text{plane: } P + \\alpha T + \\beta N,\\quad R = \\frac{1}{\\kappa} = ${tex(1 / at.curvature)}`
        : undefinedFrame;
    case 5:
      return `\\frac{dT}{ds} = \\kappa N,\\quad \\frac{dN}{ds} = -\\kappa T + \\tau B,\\quad \\frac{dB}{ds} = -\\tau N`;
    default:
      return m.space.flips.length
        ? `\\kappa \\to 0\\ \\text{near}\\ t = ${list(m.space.flips)}:\\ N = \\frac{dT/ds}{|dT/ds|}\\ \\text{turns over}`
        : `\\kappa > 0\\ \\text{everywhere: the frame never flips}`;
  }
}

function arcFormula(m: CurvatureModel, state: CurvatureState): string | null {
  const arc = m.arc!;
  const n = state.n;
  switch (state.step) {
    case 0:
      return `P(t),\\quad t \\in [0, 1]`;
    case 1:
      return `t_i = \\frac{i}{${n}},\\quad i = 0, \\dots, ${n}`;
    case 2:
      return `s(${tex(state.t)}) = \\int_0^{${tex(state.t)}} |P'(u)|\\,du = ${tex(arc.sAtT, 6)}`;
    case 3:
      return `L = s(1) = ${tex(arc.length, 6)},\\quad s(t_1) = ${tex(arc.table[1].s, 6)}`;
    default:
      return `s_k = \\frac{k L}{${n}} = k \\cdot ${tex(arc.length / n, 6)},\\quad t(s_1) = ${tex(arc.equal[1].t, 6)}`;
  }
}
