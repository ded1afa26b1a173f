import {
  type ConstraintCount,
  type Point,
  closedCubicSystem,
  constraintCount,
  gaussianEliminationOperationCount,
  thomasOperationCount,
} from '../../math';
import { memoOn } from '../../kit/memoOn';
import { LABEL_VILLAGES } from './points';
import { type Bounds, boundsOf, unionBounds } from '../../render/projection';
import { type GlobalChange, globalChange } from './globalChange';
import { SHAPE } from './methods';
import { villageNotes } from './notes';
import { CURVES, type Road, asCubics, buildRoad, quadraticControl, roadGradients } from './roads';
import { type RoadSolve, buildSolve, solvedGradients } from './solve';
import { type RoadInputs, type RoadState, segmentCount } from './state';
import { compared } from './view';

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

/** The roads through the villages and all that is built around them: the same at every step. */
export interface RoadGeometry {
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
  /** Pi + Di/3 for each gradient, where the map draws its arrow. */
  tips: Point[] | undefined;
  /** The tridiagonal system and its solve (natural and clamped roads), else null. */
  solve: RoadSolve | null;
  /** Every chosen curve of the overlay, in the order of CURVES; empty when it is off. */
  overlayCurves: OverlayCurve[];
  /** The quadratic road's control polygon P0 B0 P1 B1 … Pm and its points B1, B2, … (quadratic method, no overlay). */
  quadraticPolygon: { polygon: Point[]; controls: Point[] } | null;
  /** What is unusual about the villages, in sentences. */
  notes: string[];
  /** What "fit view" shows. */
  bounds: Bounds;
  /** The ring road's first right-hand side for x, 3(x1 − xm), shown in its formula. */
  ringRhs: number | null;
  /** The counting argument for the method (null for a ring through two villages). */
  count: ConstraintCount | null;
  cost: SolveCost | null;
  /** The global view: the road with one village moved, and mapped by an affine map (else null). */
  globalChange: GlobalChange | null;
}

/** Are the handles for the end gradients (the other roads) in play? */
const usesEndGradients = (state: RoadInputs) =>
  compared(state)
    ? state.compare.includes(4) || (state.ends && state.compare.includes(2))
    : state.road === 'clamped' || (state.road === 'hermite' && state.ends);

const usesQuadraticHandle = (state: RoadInputs) =>
  compared(state) ? state.compare.includes(1) : state.road === 'quadratic';

const plus = (p: Point, d: Point, k: number): Point => [p[0] + d[0] * k, p[1] + d[1] * k];

/** The geometry reads only the villages and the road's choices: a step or p̄ costs no new solve. */
export const roadGeometry = memoOn<RoadState, keyof RoadInputs, RoadGeometry>(
  [
    'villages',
    'road',
    'view',
    'compare',
    'quadraticGradient',
    'startGradient',
    'endGradient',
    'ends',
  ],
  (state) => {
    const v = state.villages;
    const last = v[v.length - 1];
    const box = boundsOf(v);
    const span = Math.max(box.maxX - box.minX, box.maxY - box.minY, 1e-9);
    const solve = buildSolve(state);
    const gradients = solve ? solvedGradients(solve) : roadGradients(state.road, state);
    const road = buildRoad(state.road, state, gradients);
    const a = state.startGradient;
    const b = state.endGradient;
    // The existing roads leave P0 along −D0 and Pm along Dm, a quarter of the map long.
    const reach = Math.max(box.maxX - box.minX, box.maxY - box.minY, 1) * 0.25;
    const unit = (g: Point) => reach / Math.max(1e-9, Math.hypot(g[0], g[1]));
    const otherRoads: [Point, Point] = [plus(v[0], a, -unit(a)), plus(last, b, unit(b))];
    const geometry: Omit<RoadGeometry, 'bounds'> = {
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
      tips: gradients?.map((d, i) => plus(v[i], d, 1 / 3)),
      solve,
      overlayCurves: compared(state) ? overlayCurves(state, road) : [],
      quadraticPolygon:
        !compared(state) && state.road === 'quadratic' ? controlPolygon(road, last) : null,
      notes: villageNotes(v),
      ringRhs:
        state.road === 'ring' && v.length >= 3
          ? closedCubicSystem(v.map((p) => p[0])).rhs[0]
          : null,
      count: countConditions(state),
      cost: solve ? solveCost(state, solve) : null,
      globalChange: state.view === 'global' ? globalChange(v) : null,
    };
    return { ...geometry, bounds: fitBounds(state, geometry, box) };
  },
);

/** Each curve of the overlay built once; the method's own road is not built again. */
function overlayCurves(state: RoadInputs, road: Road): OverlayCurve[] {
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

function countConditions(state: RoadInputs): ConstraintCount | null {
  const shape = SHAPE[state.road];
  if (shape.closed && state.villages.length < 3) return null;
  return constraintCount(state.villages.length, shape.degree, shape.continuity, shape.closed);
}

function solveCost(state: RoadInputs, solve: RoadSolve): SolveCost {
  const unknowns = 4 * segmentCount(state);
  return {
    unknowns,
    thomas: thomasOperationCount(solve.n, 2),
    elimination: gaussianEliminationOperationCount(unknowns, 2),
    inverse: gaussianEliminationOperationCount(unknowns, unknowns),
  };
}

/**
 * The villages, the handles in play and (for a cubic road of at most
 * FIT_PIECES pieces) its control points: the ring road bulges out of its
 * villages. The quadratic's may fly far off: its swings are the lesson.
 * The map reaches out to them by up to SWING_REACH of its size on each side,
 * so a swing a little beyond the villages shows its corner B, and a wild one
 * runs to the edge of the map without shrinking the road to a speck.
 */
function fitBounds(
  state: RoadInputs,
  geometry: Omit<RoadGeometry, 'bounds'>,
  villages: Bounds,
): Bounds {
  const points: Point[] = [];
  // The global view shows the moved road and the mapped one beside it: in the frame from its first step.
  const change = geometry.globalChange;
  if (change) points.push(...change.moved.road.pieces.flat(), ...change.mapped.mappedRoad.flat());
  if (geometry.usesQuadraticHandle) points.push(geometry.quadraticControl);
  if (geometry.usesEndGradients) points.push(...geometry.endHandles, ...geometry.otherRoads);
  const road = geometry.road;
  if (!compared(state) && state.road !== 'quadratic' && state.road !== 'roman') {
    if (road.kind === 'pieces' && road.pieces.length <= FIT_PIECES)
      points.push(...road.pieces.flat());
    // The arrows D/3 drawn from the villages (hermite's gradients, the solve's
    // back substitution): the last ones point out past the end of the road.
    if (geometry.tips && state.villages.length <= LABEL_VILLAGES) points.push(...geometry.tips);
  }
  let fitted = points.length ? unionBounds(villages, boundsOf(points)) : villages;
  const swing = geometry.quadraticPolygon?.controls;
  if (swing?.length) fitted = unionBounds(fitted, reachTowards(fitted, boundsOf(swing)));
  // The overlay's legend sits top left: room for it there, so it covers no curve.
  if (!compared(state)) return fitted;
  const width = fitted.maxX - fitted.minX;
  return { ...fitted, minX: fitted.minX - 0.45 * width };
}

/** How far beyond the fitted box (a share of its larger side) the quadratic's control points may pull the map. */
const SWING_REACH = 0.3;

/** `box` grown towards `far`, by at most SWING_REACH of the box's larger side on each side. */
function reachTowards(box: Bounds, far: Bounds): Bounds {
  const reach = SWING_REACH * Math.max(box.maxX - box.minX, box.maxY - box.minY);
  return {
    minX: Math.max(far.minX, box.minX - reach),
    minY: Math.max(far.minY, box.minY - reach),
    maxX: Math.min(far.maxX, box.maxX + reach),
    maxY: Math.min(far.maxY, box.maxY + reach),
  };
}
