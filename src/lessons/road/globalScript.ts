import { filled, fixed, pointWords, texResidue, texNumber, words } from '../../kit/format';
import { script, step } from '../../kit/script';
import type { StepAt } from '../../kit/script';
import { type FormulaParts, joined, live, livePoint, tex } from '../../render/formulaParts';
import type { Point } from '../../math';
import type { GlobalChange } from './globalChange';
import type { RoadModel } from './model';
import type { Reveal } from './script';
import type { RoadState } from './state';

// The global scene: move one village and every gradient of the natural
// spline changes; map the villages by an affine map and the road maps with
// them. Every number is computed in globalChange.ts.

type At = StepAt<RoadState, RoadModel>;

/** Up to this many gradients the formula lists every one; beyond, the first and last few. */
const LISTED = 8;

/** The step's formula from the scene's numbers (none before they exist). */
const formula =
  (write: (change: GlobalChange) => FormulaParts) =>
  ({ model }: At): string | null =>
    model.globalChange ? filled(write(model.globalChange)) : null;

/** Columns 0 … m, or the first three, ⋯, the last two. */
function columns<T>(items: readonly T[]): (T | null)[] {
  return items.length <= LISTED ? [...items] : [...items.slice(0, 3), null, ...items.slice(-2)];
}

/** D0 … Dm as two rows, x over y. */
export function gradientMatrix(gradients: readonly Point[]): FormulaParts {
  const cells = columns(gradients);
  const row = (k: 0 | 1) =>
    joined(
      cells.map((d) => (d === null ? tex`\cdots` : live(texNumber(d[k], 2)))),
      ' & ',
    );
  const names = columns(gradients.map((_, i) => i))
    .map((i) => (i === null ? '\\cdots' : `D_{${i}}`))
    .join(' & ');
  return tex`\begin{matrix} & ${names}\\ x & ${row(0)}\\ y & ${row(1)}\end{matrix}`;
}

/** |ΔD0| … |ΔDm|. */
function changesFormula({ moved }: GlobalChange): FormulaParts {
  const cells = columns(moved.changes.map((change, i) => ({ change, i })));
  return joined(
    cells.map((c) =>
      c === null ? tex`\dots` : tex`|\Delta D_{${c.i}}| = ${live(texNumber(c.change, 2))}`,
    ),
    ',\\ ',
  );
}

export const globalScript = script<RoadState, RoadModel, Reveal>(
  step('villages', ({ state }) => {
    const m = state.villages.length - 1;
    return `The ${m + 1} villages P0 … P${m}, with the natural spline to come through them`;
  }),
  step(
    'gradients',
    ({ state }) =>
      `The natural road and its gradients D0 … D${state.villages.length - 1}, each drawn as an arrow D/3`,
    formula(({ road }) => gradientMatrix(road.gradients)),
  ),
  step(
    'move',
    ({ state, model }) => {
      const moved = model.globalChange?.moved;
      if (!moved) return 'One village moves';
      const from = state.villages[moved.index];
      const to = moved.road.villages[moved.index];
      return `P${moved.index} moves ${words(moved.shift[1])} up, from ${pointWords(from)} to ${pointWords(to)}, and the system is solved again`;
    },
    formula(
      ({ road, moved }) =>
        tex`P_{${moved.index}}: ${livePoint(road.villages[moved.index])} \to ${livePoint(moved.road.villages[moved.index])}`,
    ),
  ),
  step(
    'changes',
    ({ state, model }) => {
      const moved = model.globalChange?.moved;
      const m = state.villages.length - 1;
      if (!moved) return 'Every gradient changes';
      const how = moved.changed === m + 1 ? `All ${m + 1}` : `${moved.changed} of the ${m + 1}`;
      return `${how} gradients change, even D0 and D${m} at the far ends (by ${words(moved.changes[0])} and ${words(moved.changes[m])}): the natural spline is global, where Bézier pieces and B-splines have local control`;
    },
    formula(changesFormula),
  ),
  step(
    'map',
    ({ model }) => {
      const map = model.globalChange?.mapped.map;
      if (!map) return 'An affine map moves the villages';
      return `An affine map turns the villages by ${map.turn}°, scales them by ${words(map.scale)} and shifts them by ${pointWords(map.shift)}; the road is mapped with them (dashed)`;
    },
    formula(({ mapped: { map } }) => {
      const entry = (v: number) => live(texNumber(v, 4));
      const [[a, b], [c, d]] = map.matrix;
      return tex`x \mapsto A\,x + t,\quad A = \begin{bmatrix}${entry(a)} & ${entry(b)}\\ ${entry(c)} & ${entry(d)}\end{bmatrix},\quad t = ${livePoint(map.shift)}`;
    }),
  ),
  step(
    'mapped',
    ({ model }) => {
      const mapped = model.globalChange?.mapped;
      if (!mapped) return 'The natural road through the mapped villages';
      return `The natural road through the mapped villages is the mapped road: at ${mapped.samples} values of p̄ the two are ${fixed(mapped.gap, 3)} apart, rounding aside`;
    },
    formula(
      ({ mapped }) =>
        tex`\max_{\bar p}\ \bigl|\,S(A P_i + t)(\bar p) - \bigl(A\,S(P_i)(\bar p) + t\bigr)\bigr| = ${texResidue(mapped.gap)}`,
    ),
  ),
);
