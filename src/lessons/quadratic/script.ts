import { parametricQuadraticPoint } from '../../math';
import { termRow, texNumber, texPoint, trimmed } from '../../kit/format';
import { script, step } from '../../kit/script';
import { sameXWords } from './explicit';
import type { QuadraticModel } from './model';
import { FAMILY } from './parametric';
import type { QuadraticState } from './state';

/** What the steps reveal, by name: the figure and the panel ask for these. */
export type Reveal = 'points' | 'parabola' | 'parametric' | 'ticks' | 'family' | 'rules';

/** A number in a caption: up to two decimals, trailing zeros dropped. */
const words = (v: number) => trimmed(v, 2);
/** A term after the first, ± |v| then its power: never "+ −", and nothing for a zero. */
const term = (v: number, power: string, digits: number) => {
  const size = texNumber(Math.abs(v), digits);
  return Number(size) === 0 ? '' : ` ${v < 0 ? '-' : '+'} ${size}${power}`;
};

/**
 * The lecture's argument: three points, the parabola y(x) and how it fails,
 * the parametric quadratic P(μ) instead, its speed, its family over μ1, and
 * the rules that choose μ1 from the points.
 */
export const construction = script<QuadraticState, QuadraticModel, Reveal>(
  step('points', 'Three points P₀, P₁, P₂: we want a smooth curve through them', ({ state }) =>
    state.points.map((q, i) => `P_${i} = ${texPoint(q, 3)}`).join(',\\quad '),
  ),
  step(
    'parabola',
    ({ state, model: { explicit } }) => {
      const { parabola } = explicit;
      if (parabola.kind === 'same-x') {
        return `First idea, a parabola y(x): there is none, ${sameXWords(state.points, parabola.x)}`;
      }
      return parabola.kind === 'backwards'
        ? 'First idea, a parabola y(x): it exists, but visits the points out of order'
        : 'First idea: the parabola y(x) = a₂x² + a₁x + a₀ through the three points';
    },
    ({ model: { explicit } }) => {
      if (explicit.parabola.kind === 'same-x') return null;
      const [a0, a1, a2] = explicit.parabola.coefficients;
      return `y = ${texNumber(a2, 4)}\\,x^2${term(a1, '\\,x', 4)}${term(a0, '', 4)}`;
    },
  ),
  step(
    'parametric',
    ({ state }) =>
      `Instead, a parametric quadratic P(μ): P₀ at μ = 0, P₁ at μ = μ₁ = ${words(state.mu)}, P₂ at μ = 1`,
    ({ model: { parametric } }) => {
      const [a0, a1, a2] = parametric.coefficients;
      return `P(\\mu) = ${texPoint(a2, 3)}\\,\\mu^2 + ${texPoint(a1, 3)}\\,\\mu + ${texPoint(a0, 3)}`;
    },
  ),
  step(
    'ticks',
    'Dots at equal steps of μ (0, 0.1, …, 1): where they spread out, P(μ) moves fast',
    ({ state: { points: p, mu } }) => {
      const at = (u: number) => parametricQuadraticPoint(p[0], p[1], p[2], mu, u);
      return `P(0.1) = ${texPoint(at(0.1), 3)},\\quad P(0.5) = ${texPoint(at(0.5), 3)},\\quad P(0.9) = ${texPoint(at(0.9), 3)}`;
    },
  ),
  step(
    'family',
    `One set of points, four curves, as in Figure 2: μ₁ = ${FAMILY.map(words).join(', ')}`,
    ({ state }) =>
      `\\mu_1 = ${FAMILY.map((v) => String(v)).join(',\\ ')}\\quad\\text{(and the slider's } \\mu_1 = ${words(state.mu)}\\text{)}`,
  ),
  step(
    'rules',
    'Choosing μ₁ from the points: uniform, chord length, centripetal',
    ({ model: { parametric } }) => {
      const { d0, d1, rules } = parametric;
      const [, chord, centripetal] = rules;
      return termRow(
        [
          `\\text{uniform } \\tfrac12`,
          `\\text{chord } \\frac{d_0}{d_0 + d_1} = \\frac{${texNumber(d0, 3)}}{${texNumber(d0 + d1, 3)}} = ${texNumber(chord.mu, 3)}`,
          `\\text{centripetal } \\frac{\\sqrt{d_0}}{\\sqrt{d_0} + \\sqrt{d_1}} = ${texNumber(centripetal.mu, 3)}`,
        ],
        '\\quad ',
      );
    },
  ),
);
