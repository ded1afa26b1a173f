import { type Point, bezierToPowerBasis } from '../../math';
import type { Revealed } from '../../kit/script';
import { type Derivation, deriveSystem } from './derivation';
import { type OverlayCurve, type RoadGeometry, roadGeometry } from './geometry';
import type { Reveal } from './script';
import { type ShownRoad, localParameter, showRoad } from './shownRoad';
import { type SolveProgress, solveProgress } from './solve';
import { type RoadState, chunkSize, hasSolve, segmentCount } from './state';
import { compared, dissects } from './view';

export type { OverlayCurve, SolveCost } from './geometry';

/** How far the steps so far have built the road, in rows, gradients, pieces and curves. */
export interface RoadStage {
  /** Natural and clamped: rows swept plus gradients fixed, 0 (the system) … 2n (solved); else null. */
  solveStep: number | null;
  /** Other methods: the pieces shown, from P0 (all of them at the last step). */
  pieces: number;
  /** The overlay: its first `curves` curves are drawn. */
  curves: number;
}

/** Everything the map and the panel show, computed once per state (its geometry once per road). */
export interface RoadModel extends RoadGeometry {
  state: RoadState;
  /** What the steps so far reveal (see Reveal). */
  shown: Revealed<Reveal>;
  /** How far the road is built at this step. */
  stage: RoadStage;
  /** Where the solve stands at this step (null without a solve). */
  progress: SolveProgress | null;
  /** Is the solve being stepped through, so only part of the road is built? */
  solving: boolean;
  /** Pi + Di/3 for each village, where the map draws gradient arrows (Hermite, or the solve under way). */
  gradientTips: Point[] | undefined;
  /** The method's road on the map (or what the solve has built of it); null while the overlay is shown. */
  visible: ShownRoad | null;
  /** The overlay's curves shown so far, in the order of CURVES; empty when it is off. */
  overlay: OverlayCurve[];
  /** The first sentence of each note for the map, the missing road's reason first. */
  mapNotes: string[];
  /** Where the slider's p̄ is on the method's road: its segment and local p. */
  along: { piece: number; p: number };
  /** The derivation view: the system worked out at the join nearest p̄ (else null). */
  derivation: Derivation | null;
  /** The power-basis coefficients of shown piece i (worked out when first asked for, once per state). */
  coefficients(piece: number): Point[];
}

/** The first sentence of a note: the map says it, the panel has the whole text. */
const shorten = (text: string) => text.split(/(?<=\.)\s/)[0];

/** What the steps so far have built: rows and gradients of the solve, pieces, curves. */
function stageOf(state: RoadState, shown: Revealed<Reveal>): RoadStage {
  const segments = segmentCount(state);
  if (compared(state)) return { solveStep: null, pieces: segments, curves: shown.count('answer') };
  // The derivation and the global view take the natural road as it is: no solve stepped through.
  if (dissects(state)) return { solveStep: null, pieces: segments, curves: 0 };
  if (hasSolve(state)) {
    const n = state.villages.length;
    const swept = Math.min(n, shown.count('sweep') * chunkSize(n));
    const fixed = Math.min(n, shown.count('substitution') * chunkSize(n));
    return { solveStep: swept + fixed, pieces: segments, curves: 0 };
  }
  const pieces = Math.min(segments, shown.count('segments') * chunkSize(segments));
  return { solveStep: null, pieces, curves: 0 };
}

export function derive(state: RoadState, shown: Revealed<Reveal>): RoadModel {
  const geometry = roadGeometry(state);
  const { solve, road, gradients } = geometry;
  const stage = stageOf(state, shown);
  const progress =
    solve && stage.solveStep !== null
      ? solveProgress(
          solve.n,
          Math.min(stage.solveStep, solve.n),
          Math.max(0, stage.solveStep - solve.n),
        )
      : null;
  // The system is shown and the back substitution has not reached D0 yet.
  const solving = progress !== null && shown.has('system') && !shown.last;
  const bare = shown.is('villages');
  const visible = compared(state)
    ? null
    : showRoad(
        state,
        road,
        gradients,
        solving ? progress : null,
        geometry.span,
        bare ? 0 : stage.pieces,
      );
  return {
    ...geometry,
    state,
    shown,
    stage,
    progress,
    solving,
    gradientTips:
      (state.road === 'hermite' && !compared(state)) || solving ? geometry.tips : undefined,
    visible,
    overlay: geometry.overlayCurves.slice(0, stage.curves),
    mapNotes: [...(visible?.missing ? [visible.missing] : []), ...geometry.notes].map(shorten),
    along: localParameter(state.pBar, segmentCount(state)),
    derivation:
      state.view === 'derivation' && solve ? deriveSystem(state.villages, solve, state.pBar) : null,
    coefficients: powerBasisOf(visible?.pieces ?? []),
  };
}

/** Power-basis coefficients of a piece, each worked out once, when first asked for. */
function powerBasisOf(pieces: readonly Point[][]): (piece: number) => Point[] {
  const known: Point[][] = [];
  return (piece) => (known[piece] ??= bezierToPowerBasis(pieces[piece]));
}
