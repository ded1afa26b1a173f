import { sub, texPoint, texT, words } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import type { DeCasteljauModel } from './model';
import { type DeCasteljauState, degree } from './state';

/** What the construction's steps reveal, by name: the figure and the panel ask for these. */
export type ConstructionReveal = 'points' | 'polygon' | 'level' | 'curve';

const point = (p: readonly number[]) => texPoint(p, 3);

/**
 * The construction as the lecture draws it (Figure 5): the control points,
 * the polygon (level 0), one press per level r = 1 … n, the curve traced.
 */
export const construction = script<DeCasteljauState, DeCasteljauModel, ConstructionReveal>(
  step(
    'points',
    ({ state }) =>
      `The ${degree(state) + 1} control points P₀ … P${sub(degree(state))}, and nothing else yet`,
    ({ state, model: { n } }) =>
      n > 4
        ? `P_0 = ${point(state.p[0])},\\ \\dots,\\ P_{${n}} = ${point(state.p[n])}`
        : state.p.map((q, i) => `P_{${i}} = ${point(q)}`).join(',\\ '),
  ),
  step(
    'polygon',
    'Join them in order: the control polygon, level 0',
    ({ model: { n } }) => `P_{0,i} = P_i,\\quad i = 0,\\dots,${n}`,
  ),
  repeat(
    'level',
    degree,
    ({ state, index: r, times: n }) => {
      const t = words(state.t);
      if (r === n) return `Level ${n}: one point is left, the point P(t) on the curve at t = ${t}`;
      const count = n - r + 1;
      return `Level ${r}: every edge of level ${r - 1} cut at t = ${t}, ${count} new point${count === 1 ? '' : 's'}`;
    },
    ({ state, model: { levels }, index: r, times: n }) => {
      const t = texT(state.t);
      const name = r === n ? `P(${t}) = P_{${r},0}` : `P_{${r},0}`;
      return `${name} = ${texT(1 - state.t)}\\cdot${point(levels[r - 1][0])} + ${t}\\cdot${point(levels[r - 1][1])} = ${point(levels[r][0])}`;
    },
  ),
  step(
    'curve',
    'As t runs from 0 to 1, the point P(t) traces the Bézier curve',
    ({ state, model: { n, bernsteinPoint } }) => {
      const t = texT(state.t);
      return `P(${t}) = \\sum_{i=0}^{${n}} W(${n},i,${t})\\,P_i = ${point(bernsteinPoint)}`;
    },
  ),
);
