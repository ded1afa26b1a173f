import { type FormulaParts, livePoint, tex } from '../../render/formulaParts';
import { filled } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import { methodFormula } from './methodFormula';
import type { RoadModel } from './model';
import { CURVES } from './roads';
import type { DerivationStep } from './derivationFormulas';
import { derivationScript } from './derivationScript';
import { globalScript } from './globalScript';
import { stepFormula } from './solveSteps';
import { type RoadState, chunkSize, chunks, hasSolve, segmentCount } from './state';
import { compared } from './view';

/**
 * What the steps reveal, by name: the villages; with the overlay, one answer
 * a press; for the natural and clamped roads, the system, then chunks of its
 * forward sweep and of its back substitution; for the others, their
 * construction, then chunks of the road's segments from P0. The derivation
 * and the global view have steps of their own (derivationScript.ts,
 * globalScript.ts).
 */
export type Reveal =
  | 'villages'
  | 'answer'
  | 'system'
  | 'sweep'
  | 'substitution'
  | 'construction'
  | 'segments'
  | Exclude<DerivationStep, 'villages' | 'system'>
  | 'gradients'
  | 'move'
  | 'changes'
  | 'map'
  | 'mapped';

/** The method's own road is built (no overlay): by a solve, or piece by piece. */
const solved = (state: RoadState) => !compared(state) && hasSolve(state);
const pieceByPiece = (state: RoadState) => !compared(state) && !hasSolve(state);

/** "row 3" or "rows 3–8": a chunk of rows or pieces. */
const span = (word: string, from: number, to: number) =>
  from === to ? `${word} ${from}` : `${word}s ${from}–${to}`;

/** What each method builds before its first piece (the Roman road builds nothing). */
const CONSTRUCTION: Partial<Record<RoadState['road'], string>> = {
  quadratic: 'One chosen gradient D0 at P0 fixes the first control point, B0 = P0 + D0/2',
  hermite:
    'At each village the gradient of the parabola through it and its neighbours, Dᵢ = (Pᵢ₊₁ − Pᵢ₋₁)/2',
  ring: 'The cyclic system: every row is [1 4 1], and the rows wrap round from Pm to P0',
};

/** The solve's step for x, on one line (y is worked out the same way, in the panel). */
const solveFormula = ({ model }: { model: RoadModel }) => {
  const { solve, progress, stage } = model;
  return solve && progress && stage.solveStep !== null
    ? filled(stepFormula(solve, 0, stage.solveStep, progress.row, true))
    : null;
};

/** The method's formula; while the quadratic road is built, the control point the step added. */
const buildFormula = ({ state, model }: { state: RoadState; model: RoadModel }) =>
  filled(state.road === 'quadratic' ? quadraticStepFormula(model, state) : methodFormula(model));

/** The clicker's script for the road (see Reveal). */
export const roadScript = script<RoadState, RoadModel, Reveal>(
  step('villages', ({ state }) => {
    const m = state.villages.length - 1;
    return `The ${m + 1} villages P0 … P${m}, in the order the road visits them`;
  }),
  repeat(
    'answer',
    (s) => (compared(s) ? Math.max(1, s.compare.length) : 0),
    ({ state, index }) => {
      const order = [...state.compare].sort((a, b) => a - b);
      // With no answer ticked the overlay still has its one step: say so.
      if (!order.length) return 'No answer is ticked to draw side by side';
      return `Answer ${index} of ${order.length}: ${CURVES[order[index - 1]].name}`;
    },
  ),
  repeat(
    'system',
    (s) => (solved(s) ? 1 : 0),
    ({ state }) =>
      state.road === 'clamped'
        ? 'The system for D0 … Dm: [1 4 1] inside, first and last rows fixed to the given gradients'
        : 'The system for D0 … Dm: [1 4 1] inside, [2 1] and [1 2] for zero curvature at the ends',
    solveFormula,
  ),
  repeat(
    'sweep',
    (s) => (solved(s) ? chunks(s.villages.length) : 0),
    ({ state, index }) => {
      const n = state.villages.length;
      const size = chunkSize(n);
      const swept = Math.min(n, index * size);
      const from = Math.max(0, swept - size);
      return `Forward sweep: ${span('row', from, swept - 1)} ${from === swept - 1 ? 'becomes' : 'become'} [1 γ | Γ]`;
    },
    solveFormula,
  ),
  repeat(
    'substitution',
    (s) => (solved(s) ? chunks(s.villages.length) : 0),
    ({ state, index }) => {
      const n = state.villages.length;
      const size = chunkSize(n);
      const fixed = Math.min(n, index * size);
      const from = n - fixed;
      const to = Math.min(n - 1, from + size - 1);
      return fixed === n
        ? 'Back substitution reaches D0: every gradient is known, the whole road is built'
        : `Back substitution: ${from === to ? `D${from}` : `D${from} … D${to}`} fixed, the road grows back from Pm`;
    },
    solveFormula,
  ),
  repeat(
    'construction',
    (s) => (pieceByPiece(s) && CONSTRUCTION[s.road] ? 1 : 0),
    ({ state }) => CONSTRUCTION[state.road] ?? '',
    buildFormula,
  ),
  repeat(
    'segments',
    (s) => (pieceByPiece(s) ? chunks(segmentCount(s)) : 0),
    ({ state, index, times }) => {
      const total = segmentCount(state);
      if (index === times)
        return `The whole road: p̄ runs from 0 at P0 to ${total} at ${state.road === 'ring' ? 'P0 again' : `P${state.villages.length - 1}`}`;
      const size = chunkSize(total);
      const built = Math.min(total, index * size);
      // What the figure shows: every segment from P0 to here, the newest last.
      const first = Math.max(0, built - size);
      const newest = first > 0 ? ` (new: ${span('segment', first, built - 1)})` : '';
      return `Built so far: ${span('segment', 0, built - 1)} of the ${total}${newest}`;
    },
    buildFormula,
  ),
);

/** The steps a state walks: its view's (the derivation and the global view have their own). */
export function scriptOf(state: RoadState) {
  if (state.view === 'derivation') return derivationScript;
  if (state.view === 'global') return globalScript;
  return roadScript;
}

/** An edit that changes the number of steps keeps a road shown to its end at its (new) end. */
export const keepShownToEnd = (before: RoadState, after: RoadState): RoadState => ({
  ...after,
  step: scriptOf(after).keepEnd(before, before.step, after),
});

/** The state with its whole road shown: the last step (a method or the overlay just chosen). */
export const shownToEnd = (state: RoadState): RoadState => ({
  ...state,
  step: scriptOf(state).lastStep(state),
});

/**
 * The caption's formula while the quadratic road is built: the control point
 * the step added, on one line (the panel lists them all; the caption has room
 * for one line from the back of the hall).
 */
function quadraticStepFormula(model: RoadModel, state: RoadState): FormulaParts {
  const road = model.road;
  const controls = road.kind === 'pieces' ? road.pieces.map((piece) => piece[1]) : [];
  const last = Math.min(model.stage.pieces, controls.length) - 1;
  if (last < 1)
    return tex`D_0 = ${livePoint(state.quadraticGradient)},\quad B_0 = P_0 + \tfrac12 D_0 = ${livePoint(model.quadraticControl)}`;
  return tex`B_{${last}} = 2P_{${last}} - B_{${last - 1}} = ${livePoint(controls[last])}`;
}
