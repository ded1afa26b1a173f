import {
  type ConstraintCount,
  type Point,
  bezierToPowerBasis,
  closedCubicSystem,
  constraintCount,
  gaussianEliminationOperationCount,
  thomasOperationCount,
} from '../../math';
import { type Bounds, boundsOf, unionBounds } from '../../render/projection';
import { SHAPE } from './methods';
import { villageNotes } from './notes';
import { type ShownRoad, localParameter, showRoad } from './shownRoad';
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
  solveProgress,
  solvedGradients,
} from './solve';
import { type RoadStage, type RoadState, segmentCount, stage } from './state';

/** Up to this many pieces the method's road is fitted into the map whole (control points and all). */
const FIT_PIECES = 100;

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
  /** Pi + Di/3 for each village, where the map draws gradient arrows (Hermite, or the solve under way). */
  gradientTips: Point[] | undefined;
  /** The tridiagonal system and its solve (natural and clamped roads), else null. */
  solve: RoadSolve | null;
  /** Where the solve stands at this step (null without a solve). */
  progress: SolveProgress | null;
  /** Is the solve being stepped through, so only part of the road is built? */
  solving: boolean;
  /** What the step shows. */
  stage: RoadStage;
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
  const at = stage(state);
  const progress = solve && at.solveStep !== null ? solveProgress(solve.n, at.solveStep) : null;
  const solving = !at.bare && progress !== null && at.solveStep! < 2 * solve!.n;
  const shown = state.overlay
    ? null
    : showRoad(state, road, gradients, solving ? progress : null, span, at.bare ? 0 : at.pieces);

  const a = startGradient(state);
  const b = endGradient(state);
  // The existing roads leave P0 along −D0 and Pm along Dm, a quarter of the map long.
  const reach = Math.max(box.maxX - box.minX, box.maxY - box.minY, 1) * 0.25;
  const unit = (g: Point) => reach / Math.max(1e-9, Math.hypot(g[0], g[1]));
  const otherRoads: [Point, Point] = [plus(v[0], a, -unit(a)), plus(last, b, unit(b))];
  const notes = villageNotes(v);
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
    gradientTips:
      (state.road === 'hermite' && !state.overlay) || solving
        ? gradients?.map((d, i) => plus(v[i], d, 1 / 3))
        : undefined,
    solve,
    progress,
    solving,
    stage: at,
    shown,
    overlay: state.overlay ? overlayCurves(state, road).slice(0, at.curves) : [],
    quadraticPolygon:
      !state.overlay && state.road === 'quadratic' ? controlPolygon(road, last) : null,
    notes,
    mapNotes: [...(shown?.missing ? [shown.missing] : []), ...notes].map(shorten),
    along: localParameter(state.s, segmentCount(state)),
    ringRhs:
      state.road === 'ring' && v.length >= 3 ? closedCubicSystem(v.map((p) => p[0])).rhs[0] : null,
    count: countConditions(state),
    cost: solve ? solveCost(state, solve) : null,
    coefficients: powerBasisOf(shown?.pieces ?? []),
  };
  return { ...model, bounds: fitBounds(model, box) };
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
function fitBounds(model: Omit<RoadModel, 'bounds'>, villages: Bounds): Bounds {
  const { state } = model;
  const points: Point[] = [];
  if (model.usesQuadraticHandle) points.push(model.quadraticControl);
  if (model.usesEndGradients) points.push(...model.endHandles, ...model.otherRoads);
  const road = model.road;
  if (!state.overlay && state.road !== 'quadratic' && state.road !== 'roman') {
    if (road.kind === 'pieces' && road.pieces.length <= FIT_PIECES)
      points.push(...road.pieces.flat());
  }
  const fitted = points.length ? unionBounds(villages, boundsOf(points)) : villages;
  // The overlay's legend sits top left: room for it there, so it covers no curve.
  if (!state.overlay) return fitted;
  const width = fitted.maxX - fitted.minX;
  return { ...fitted, minX: fitted.minX - 0.45 * width };
}
