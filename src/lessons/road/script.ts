import { type FormulaParts, livePoint, tex } from '../../render/formulaParts';
import { filled } from '../../kit/format';
import { methodFormula } from './methodFormula';
import type { RoadModel } from './model';
import { CURVES } from './roads';
import { stepFormula } from './solveSteps';
import { type RoadState, chunkSize, hasSolve, segmentCount, stage, stepCount } from './state';

// The clicker's script for the road: the villages, then the method's
// construction (its gradients, its first control point, its system) and the
// road piece by piece; the natural and clamped roads build their system row by
// row and solve it; the overlay adds one answer at a time.

/** "row 3" or "rows 3–8": a chunk of rows or pieces. */
const span = (word: string, from: number, to: number) =>
  from === to ? `${word} ${from}` : `${word}s ${from}–${to}`;

const AID: Partial<Record<RoadState['road'], string>> = {
  quadratic: 'One chosen gradient D0 at P0 fixes the first control point, B0 = P0 + D0/2',
  hermite:
    'At each village the gradient of the parabola through it and its neighbours, Dᵢ = (Pᵢ₊₁ − Pᵢ₋₁)/2',
  ring: 'The cyclic system: every row is [1 4 1], and the rows wrap round from Pm to P0',
};

export function describeStep(state: RoadState, k: number): string {
  const m = state.v.length - 1;
  if (k === 0) return `The ${m + 1} villages P0 … P${m}, in the order the road visits them`;
  const at = stage({ ...state, step: k });
  if (state.overlay) {
    const order = [...state.compare].sort((a, b) => a - b);
    return `Answer ${k} of ${order.length}: ${CURVES[order[k - 1]].name}`;
  }
  if (hasSolve(state)) {
    const n = state.v.length;
    const s = at.solveStep ?? 0;
    const size = chunkSize(n);
    if (s === 0)
      return state.road === 'clamped'
        ? 'The system for D0 … Dm: [1 4 1] inside, first and last rows fixed to the given gradients'
        : 'The system for D0 … Dm: [1 4 1] inside, [2 1] and [1 2] for zero curvature at the ends';
    if (s <= n) {
      const from = Math.max(0, s - size);
      return `Forward sweep: ${span('row', from, s - 1)} ${from === s - 1 ? 'becomes' : 'become'} [1 γ | Γ]`;
    }
    const fixed = s - n;
    const from = n - fixed;
    const to = Math.min(n - 1, from + size - 1);
    return fixed === n
      ? 'Back substitution reaches D0: every gradient is known, the whole road is built'
      : `Back substitution: ${from === to ? `D${from}` : `D${from} … D${to}`} fixed, the road grows back from Pm`;
  }
  const aid = AID[state.road];
  if (aid && k === 1) return aid;
  const total = segmentCount(state);
  if (at.pieces >= total && k === stepCount(state))
    return `The whole road: p̄ runs from 0 at P0 to ${total} at ${state.road === 'ring' ? 'P0 again' : `P${m}`}`;
  const size = chunkSize(total);
  return `Built so far: ${span('segment', Math.max(0, at.pieces - size), at.pieces - 1)} of 0–${total - 1}`;
}

export function roadFormula(model: RoadModel, state: RoadState): string | null {
  if (state.step === 0) return null;
  const { solve, progress, stage: at } = model;
  // The solve's step for x (y is worked out the same way, in the panel).
  if (solve && progress && at.solveStep !== null)
    return filled(stepFormula(solve, 0, at.solveStep, progress.row, true));
  if (state.overlay) return null;
  if (state.road === 'quadratic') return filled(quadraticStepFormula(model, state));
  return filled(methodFormula(model));
}

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
    return tex`D_0 = ${livePoint(state.q)},\quad B_0 = P_0 + \tfrac12 D_0 = ${livePoint(model.quadraticControl)}`;
  return tex`B_{${last}} = 2P_{${last}} - B_{${last - 1}} = ${livePoint(controls[last])}`;
}
