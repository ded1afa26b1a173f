import {
  type ConstraintCount,
  type Point,
  bezierPieceBoxes,
  bezierPoint,
  bezierToPowerBasis,
  closedCubicSystem,
  constraintCount,
  gaussianEliminationOperationCount,
  thomasOperationCount,
} from '../../math';
import { type Bounds, boundsOf } from '../../render/projection';
import { SHAPE } from './methods';
import { villageNotes } from './notes';
import { type CurvatureComb, curvatureComb, parameterTicks } from './roadMarks';
import {
  CURVES,
  type Road,
  asCubics,
  buildRoad,
  endGradient,
  quadraticControl,
  roadGradients,
  startGradient,
} from './roads';
import {
  type RoadSolve,
  type SolveProgress,
  buildSolve,
  builtPieces,
  solveProgress,
  solvedGradients,
} from './solve';
import { type RoadState, isSolving, segmentCount } from './state';

/** Up to this many segments the ticks of p̄ are worked out (and drawn). */
export const TICK_SEGMENTS = 60;
/** Up to this many pieces the method's road is fitted into the map whole (control points and all). */
const FIT_PIECES = 100;

/** The road as the map shows it: the finished road, or the pieces the solve has built so far. */
export interface ShownRoad {
  /** Bézier pieces (degree 1, 2 or 3); piece i is segment offset + i. Empty when there are none (yet). */
  pieces: Point[][];
  /** The same pieces as cubics, for drawing. */
  cubics: Point[][];
  /** The box of each piece's control points, for hit tests (see bezierPieceBoxes). */
  boxes: Float64Array;
  /** The segment of pieces[0]: while the solve runs only the last segments are built. */
  offset: number;
  /** Why the method draws no road here (a ring through two villages), else null. */
  missing: string | null;
  /** The marker at p̄ once the road is built: its piece, local p and place. */
  marker: { piece: number; p: number; point: Point } | null;
  /** Ticks at every quarter of p̄ (see parameterTicks), on a built road of at most TICK_SEGMENTS segments. */
  ticks: Float64Array | null;
  /** The curvature comb, when it is switched on. */
  comb: CurvatureComb | null;
}

/** One curve of the overlay. */
export interface OverlayCurve {
  /** Its number in CURVES (and in the link). */
  index: number;
  road: Road;
  /** Its pieces as cubics, for drawing (null for a sampled or missing curve). */
  cubics: Point[][] | null;
}

/** What the solve costs, against the dense alternatives (for the panel's note). */
export interface SolveCost {
  /** N = 4 × segments: unknown coefficients of the whole road. */
  unknowns: number;
  thomas: number;
  elimination: number;
  inverse: number;
}

/** Everything the map and the panel show, computed once per state. */
export interface RoadModel {
  state: RoadState;
  /** The larger side of the villages' box: the size of the map. */
  span: number;
  usesQuadraticHandle: boolean;
  usesEndGradients: boolean;
  /** B0 = P0 + D0/2, the first control point of the quadratic pieces (its square handle). */
  quadraticControl: Point;
  /** The tips of D0/3 and Dm/3: the handles of the end gradients. */
  endHandles: [Point, Point];
  /** Where the existing roads the new one joins at P0 and Pm come from: a quarter of the map away. */
  otherRoads: [Point, Point];
  /** Those roads up to P0 and from Pm, as cubics for drawing. */
  otherRoadways: Point[][];
  /** The method's road, finished. */
  road: Road;
  /** The method's gradients D0 … Dm (Hermite, natural, clamped, ring), else undefined. */
  gradients: Point[] | undefined;
  /** Pi + Di/3 for each village: the tips of the gradient arrows. */
  gradientTips: Point[] | undefined;
  /** The tridiagonal system and its solve (natural and clamped roads), else null. */
  solve: RoadSolve | null;
  /** Where the solve stands at this step (null without a solve). */
  progress: SolveProgress | null;
  /** Is the solve being stepped through, so only part of the road is built? */
  solving: boolean;
  /** The method's road on the map; null while the overlay is shown. */
  shown: ShownRoad | null;
  /** The overlay's curves in the order of CURVES; empty when it is off. */
  overlay: OverlayCurve[];
  /** The quadratic road's control polygon P0 B0 P1 B1 … Pm and its points B1, B2, … (quadratic method, no overlay). */
  quadraticPolygon: { polygon: Point[]; controls: Point[] } | null;
  /** What is unusual about the villages, in sentences. */
  notes: string[];
  /** The first sentence of each note for the map, the missing road's reason first. */
  mapNotes: string[];
  /** What "fit view" shows. */
  bounds: Bounds;
  /** Where the slider's p̄ is on the method's road: its segment and local p. */
  along: { piece: number; p: number };
  /** The ring road's first right-hand side for x, 3(x1 − xm), shown in its formula. */
  ringRhs: number | null;
  /** The counting argument for the method (null for a ring through two villages). */
  count: ConstraintCount | null;
  cost: SolveCost | null;
  /** The power-basis coefficients of shown piece i (worked out when first asked for, once per state). */
  coefficients(piece: number): Point[];
}

/** The piece and local parameter p of the global p̄ on a road of `count` pieces. */
export function localParameter(s: number, count: number): { piece: number; p: number } {
  const piece = Math.max(0, Math.min(Math.floor(s), count - 1));
  return { piece, p: s - piece };
}

/** Are the handles for the end gradients (the other roads) in play? */
const usesEndGradients = (state: RoadState) =>
  state.overlay
    ? state.compare.includes(4) || (state.ends && state.compare.includes(2))
    : state.road === 'clamped' || (state.road === 'hermite' && state.ends);

const usesQuadraticHandle = (state: RoadState) =>
  state.overlay ? state.compare.includes(1) : state.road === 'quadratic';

const plus = (p: Point, d: Point, k: number): Point => [p[0] + d[0] * k, p[1] + d[1] * k];

/** The first sentence of a note: the map says it, the panel has the whole text. */
const shorten = (text: string) => text.split(/(?<=\.)\s/)[0];

export function derive(state: RoadState): RoadModel {
  const v = state.v;
  const last = v[v.length - 1];
  const box = boundsOf(v);
  const span = Math.max(box.maxX - box.minX, box.maxY - box.minY, 1e-9);
  const solve = buildSolve(state);
  const gradients = solve ? solvedGradients(solve) : roadGradients(state.road, state);
  const road = buildRoad(state.road, state, gradients);
  const progress = solve && solveProgress(solve.n, state.step);
  const solving = isSolving(state);
  const shown = state.overlay
    ? null
    : showRoad(state, road, gradients, solving ? progress : null, span);

  const a = startGradient(state);
  const b = endGradient(state);
  // The existing roads leave P0 along −D0 and Pm along Dm, a quarter of the map long.
  const reach = Math.max(box.maxX - box.minX, box.maxY - box.minY, 1) * 0.25;
  const unit = (g: Point) => reach / Math.max(1e-9, Math.hypot(g[0], g[1]));
  const otherRoads: [Point, Point] = [plus(v[0], a, -unit(a)), plus(last, b, unit(b))];
  const model: Omit<RoadModel, 'bounds'> = {
    state,
    span,
    usesQuadraticHandle: usesQuadraticHandle(state),
    usesEndGradients: usesEndGradients(state),
    quadraticControl: quadraticControl(state),
    endHandles: [plus(v[0], a, 1 / 3), plus(last, b, 1 / 3)],
    otherRoads,
    otherRoadways: asCubics([
      [otherRoads[0], v[0]],
      [last, otherRoads[1]],
    ]),
    road,
    gradients,
    gradientTips: gradients?.map((d, i) => plus(v[i], d, 1 / 3)),
    solve,
    progress,
    solving,
    shown,
    overlay: state.overlay ? overlayCurves(state, road) : [],
    quadraticPolygon:
      !state.overlay && state.road === 'quadratic' ? controlPolygon(road, last) : null,
    notes: villageNotes(v),
    mapNotes: [],
    along: localParameter(state.s, segmentCount(state)),
    ringRhs:
      state.road === 'ring' && v.length >= 3 ? closedCubicSystem(v.map((p) => p[0])).rhs[0] : null,
    count: countConditions(state),
    cost: solve ? solveCost(state, solve) : null,
    coefficients: powerBasisOf(shown?.pieces ?? []),
  };
  model.mapNotes = [...(shown?.missing ? [shown.missing] : []), ...model.notes].map(shorten);
  return { ...model, bounds: fitBounds(model) };
}

function showRoad(
  state: RoadState,
  road: Road,
  gradients: Point[] | undefined,
  progress: SolveProgress | null,
  span: number,
): ShownRoad {
  const pieces = progress
    ? builtPieces(state.v, gradients!, progress)
    : road.kind === 'pieces'
      ? road.pieces
      : [];
  const built = !progress && pieces.length > 0;
  const marker = built ? localParameter(state.s, pieces.length) : null;
  return {
    pieces,
    cubics: asCubics(pieces),
    boxes: bezierPieceBoxes(pieces),
    offset: segmentCount(state) - pieces.length,
    missing: road.kind === 'missing' ? road.why : null,
    marker: marker && { ...marker, point: bezierPoint(pieces[marker.piece], marker.p) },
    ticks: built && pieces.length <= TICK_SEGMENTS ? parameterTicks(pieces) : null,
    comb: state.comb ? curvatureComb(pieces, span / 10, pieces.length > 100 ? 6 : 16) : null,
  };
}

/** Each curve of the overlay built once; the method's own road is not built again. */
function overlayCurves(state: RoadState, road: Road): OverlayCurve[] {
  return [...state.compare]
    .sort((x, y) => x - y)
    .map((index) => {
      const curve = CURVES[index].id === state.road ? road : buildRoad(CURVES[index].id, state);
      return {
        index,
        road: curve,
        cubics: curve.kind === 'pieces' ? asCubics(curve.pieces) : null,
      };
    });
}

/** P0 B0 P1 B1 … Pm: each Bi is the reflection of B(i−1) in Pi. */
function controlPolygon(road: Road, last: Point) {
  if (road.kind !== 'pieces') return null;
  return {
    polygon: [...road.pieces.flatMap((piece) => piece.slice(0, 2)), last],
    controls: road.pieces.slice(1).map((piece) => piece[1]),
  };
}

function countConditions(state: RoadState): ConstraintCount | null {
  const shape = SHAPE[state.road];
  if (shape.closed && state.v.length < 3) return null;
  return constraintCount(state.v.length, shape.degree, shape.continuity, shape.closed);
}

function solveCost(state: RoadState, solve: RoadSolve): SolveCost {
  const unknowns = 4 * segmentCount(state);
  return {
    unknowns,
    thomas: thomasOperationCount(solve.n, 2),
    elimination: gaussianEliminationOperationCount(unknowns, 2),
    inverse: gaussianEliminationOperationCount(unknowns, unknowns),
  };
}

/** Power-basis coefficients of a piece, each worked out once, when first asked for. */
function powerBasisOf(pieces: readonly Point[][]): (piece: number) => Point[] {
  const known: Point[][] = [];
  return (piece) => (known[piece] ??= bezierToPowerBasis(pieces[piece]));
}

/**
 * The villages, the handles in play and (for a cubic road of at most
 * FIT_PIECES pieces) its control points: the ring road bulges out of its
 * villages. The quadratic's may fly far off: its swings are the lesson,
 * shown to the edge of the map.
 */
function fitBounds(model: Omit<RoadModel, 'bounds'>): Bounds {
  const { state } = model;
  const points: Point[] = [...state.v];
  if (model.usesQuadraticHandle) points.push(model.quadraticControl);
  if (model.usesEndGradients) points.push(...model.endHandles, ...model.otherRoads);
  const road = model.road;
  if (!state.overlay && state.road !== 'quadratic' && state.road !== 'roman') {
    if (road.kind === 'pieces' && road.pieces.length <= FIT_PIECES)
      points.push(...road.pieces.flat());
  }
  return boundsOf(points);
}
