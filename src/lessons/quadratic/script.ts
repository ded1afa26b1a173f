import { type Point, parametricQuadraticPoint } from '../../math';
import { texNumber, texPoint, trimmed } from '../../kit/format';
import { explicitParabola, sameXWords } from './explicit';
import type { QuadraticModel } from './model';
import { FAMILY, type QuadraticState, STEP } from './state';

/** A number in a caption: up to two decimals, trailing zeros dropped. */
const words = (v: number) => trimmed(v, 2);
/** A term after the first, ± |v| then its power: never "+ −", and nothing for a zero. */
const term = (v: number, power: string, digits: number) => {
  const size = texNumber(Math.abs(v), digits);
  return Number(size) === 0 ? '' : ` ${v < 0 ? '-' : '+'} ${size}${power}`;
};

/** The caption of step k of the construction. */
export function describeStep(state: QuadraticState, k: number): string {
  switch (k) {
    case STEP.points:
      return 'Three points P₀, P₁, P₂: we want a smooth curve through them';
    case STEP.parabola: {
      const parabola = explicitParabola(state.p);
      if (parabola.kind === 'same-x') {
        return `First idea, a parabola y(x): there is none, ${sameXWords(state.p, parabola.x)}`;
      }
      return parabola.kind === 'backwards'
        ? 'First idea, a parabola y(x): it exists, but visits the points out of order'
        : 'First idea: the parabola y(x) = a₂x² + a₁x + a₀ through the three points';
    }
    case STEP.parametric:
      return `Instead, a parametric quadratic P(μ): P₀ at μ = 0, P₁ at μ = μ₁ = ${words(state.mu)}, P₂ at μ = 1`;
    case STEP.ticks:
      return 'Dots at equal steps of μ (0, 0.1, …, 1): where they spread out, P(μ) moves fast';
    case STEP.family:
      return `One set of points, many curves: μ₁ = ${FAMILY.map(words).join(', ')}`;
    default:
      return 'Choosing μ₁ from the points: uniform, chord length, centripetal';
  }
}

/** The formula of the current step with its numbers (TeX); null where the step has none. */
export function stepFormula(m: QuadraticModel, state: QuadraticState): string | null {
  const { p, mu } = state;
  switch (state.step) {
    case STEP.points:
      return p.map((q: Point, i) => `P_${i} = ${texPoint(q, 3)}`).join(',\\quad ');
    case STEP.parabola: {
      const parabola = m.explicit.parabola;
      if (parabola.kind === 'same-x') return null;
      const [a0, a1, a2] = parabola.coefficients;
      return `y = ${texNumber(a2, 4)}\\,x^2${term(a1, '\\,x', 4)}${term(a0, '', 4)}`;
    }
    case STEP.parametric: {
      const [a0, a1, a2] = m.parametric.coefficients;
      return `P(\\mu) = ${texPoint(a2, 3)}\\,\\mu^2 + ${texPoint(a1, 3)}\\,\\mu + ${texPoint(a0, 3)}`;
    }
    case STEP.ticks: {
      const at = (u: number) => parametricQuadraticPoint(p[0], p[1], p[2], mu, u);
      return `P(0.1) = ${texPoint(at(0.1), 3)},\\quad P(0.5) = ${texPoint(at(0.5), 3)},\\quad P(0.9) = ${texPoint(at(0.9), 3)}`;
    }
    case STEP.family:
      return `\\mu_1 = ${FAMILY.map((v) => String(v)).join(',\\ ')}\\quad\\text{(and the slider's } \\mu_1 = ${words(mu)}\\text{)}`;
    default: {
      const { d0, d1, rules } = m.parametric;
      const [, chord, centripetal] = rules;
      return `\\text{uniform } \\tfrac12,\\quad \\text{chord } \\frac{d_0}{d_0 + d_1} = \\frac{${texNumber(d0, 3)}}{${texNumber(d0 + d1, 3)}} = ${texNumber(chord.mu, 3)},\\quad \\text{centripetal } \\frac{\\sqrt{d_0}}{\\sqrt{d_0} + \\sqrt{d_1}} = ${texNumber(centripetal.mu, 3)}`;
    }
  }
}
