import {
  type Continuity,
  type Point,
  type SurfaceConstruction,
  bezierBasisMatrix,
  bezierJointContinuity,
  bezierPoint,
  sampleBezier,
  bezierSurfaceDerivatives,
  bezierSurfaceNormal,
  cross,
  onOneSpot,
  surfaceColumnPoints,
  surfaceDeCasteljau,
  surfaceRowPoints,
  surfaceWeights,
} from '../../math';
import { memoOn } from '../../kit/memoOn';
import type { Revealed } from '../../kit/script';
import { boundsOf } from '../../render/projection';
import type { Bounds } from '../../render/projection';
import type { Reveal } from './scripts';
import { type SurfaceState, coordinateIndex } from './state';

/** Quads per side of the shaded patch: 16 × 16 flat facets, sampled once per state. */
export const FACETS = 16;
/** Iso-parameter lines per direction (u, v = 0, 1/8, …, 1). */
export const ISO_LINES = 8;
/** Segments of every sampled curve. */
const CURVE_SEGMENTS = 32;

/** A patch sampled for drawing. */
export interface PatchSamples {
  /** `grid[i][j]` = P(i/FACETS, j/FACETS): the corners of the shaded facets. */
  grid: Point[][];
  /** Iso-curves u = i/ISO_LINES, each a polyline in v. */
  uLines: Point[][];
  /** Iso-curves v = j/ISO_LINES, each a polyline in u. */
  vLines: Point[][];
  /**
   * The same iso-curves along the facets' edges (every other grid line): on a
   * shaded patch they lie on its flat facets instead of cutting through them,
   * and half as many depth-sorted pieces keep a frame within budget.
   */
  facetLines: Point[][];
  /** The four boundary curves along the facets' edges (drawn when the edges are not drawn over them). */
  facetEdges: Point[][];
}

/** The matrix form of one coordinate of P(u, v), x(u, v) = U·M·B·Mᵀ·Vᵀ (or y, z), with its numbers. */
export interface MatrixForm {
  /** [1 u u² u³] and [1 v v² v³]. */
  U: number[];
  V: number[];
  /** The power-basis matrix of the cubic Bézier curve (row k: the coefficients of uᵏ). */
  M: number[][];
  /** The chosen coordinate of the 16 control points, `B[m][n]`. */
  B: number[][];
  /** U·M = (f0(u), …, f3(u)) and V·M = (f0(v), …, f3(v)). */
  UM: number[];
  VM: number[];
  /** (U·M)·B, a row of four numbers. */
  UMB: number[];
  value: number;
}

/** How the two patches of the joined pair meet along their shared edge. */
export interface JoinReport {
  /** Per column n of the pair: the continuity of the curves P(·,n) then Q(·,n) at the edge. */
  columns: Continuity[];
  /** The weakest of them: what the surface has. */
  weakest: Continuity;
}

/** The first patch at (u, v): its point, tangents, row and column curves, weights. */
export interface PointGeometry {
  /** P(u, v) by the Bernstein double sum. */
  point: Point;
  du: Point;
  dv: Point;
  /** ∂P/∂u × ∂P/∂v and its unit vector (null where the tangent plane is undefined). */
  crossProduct: Point;
  normal: Point | null;
  /** r_m(v) = Σn fn(v) P(m,n): the control points of the iso-curve v = const. */
  rowPoints: Point[];
  /** c_n(u) = Σm fm(u) P(m,n): the control points of the iso-curve u = const. */
  columnPoints: Point[];
  /** Row m of the net as a curve in v, sampled. */
  rowCurves: Point[][];
  /** Column n of the net as a curve in u, sampled. */
  columnCurves: Point[][];
  /** The iso-curve v = const through the point (a curve in u), and u = const (a curve in v). */
  isoV: Point[];
  isoU: Point[];
  uThenV: SurfaceConstruction;
  vThenU: SurfaceConstruction;
  /** fm(u)·fn(v), `weights[m][n]`, and their sum. */
  weights: number[][];
  /** fm(u) = Σn fm(u)·fn(v), the share of row m; fn(v), the share of column n. */
  rowShares: number[];
  columnShares: number[];
  weightSum: number;
  /** All 16 control points on one spot: the patch is that point (the figure says so). */
  oneSpot: boolean;
}

export interface SurfaceModel extends PointGeometry {
  state: SurfaceState;
  /** What the scene's steps so far reveal. */
  shown: Revealed<Reveal>;
  patch: PatchSamples;
  /** The second patch, in the scene of two joined patches; null otherwise. */
  second: PatchSamples | null;
  join: JoinReport | null;
  matrix: MatrixForm;
  bounds: Bounds;
}

/** Everything about the first patch at (u, v): it reads only the net, u and v, so a step costs nothing. */
const atPoint = memoOn<SurfaceState, 'net' | 'u' | 'v', PointGeometry>(
  ['net', 'u', 'v'],
  ({ net, u, v }) => {
    const jet = bezierSurfaceDerivatives(net, u, v);
    let normal: Point | null;
    try {
      normal = bezierSurfaceNormal(net, u, v);
    } catch {
      normal = null;
    }
    const rowPoints = surfaceRowPoints(net, v);
    const columnPoints = surfaceColumnPoints(net, u);
    const weights = surfaceWeights(4, 4, u, v);
    return {
      oneSpot: onOneSpot(net.flat()),
      point: jet.point,
      du: jet.du,
      dv: jet.dv,
      crossProduct: cross(jet.du, jet.dv),
      normal,
      rowPoints,
      columnPoints,
      rowCurves: net.map((row) => sampleCurve(row)),
      columnCurves: net[0].map((_, n) => sampleCurve(net.map((row) => row[n]))),
      isoV: sampleCurve(rowPoints),
      isoU: sampleCurve(columnPoints),
      uThenV: surfaceDeCasteljau(net, u, v, 'u-then-v'),
      vThenU: surfaceDeCasteljau(net, u, v, 'v-then-u'),
      weights,
      rowShares: weights.map((row) => row.reduce((sum, w) => sum + w, 0)),
      columnShares: weights[0].map((_, n) => weights.reduce((sum, row) => sum + row[n], 0)),
      weightSum: weights.flat().reduce((sum, w) => sum + w, 0),
    };
  },
);

/** The patches sampled: once per net, whatever u, v or the step. */
const firstPatch = memoOn<SurfaceState, 'net', PatchSamples>(['net'], ({ net }) =>
  samplePatch(net),
);
const secondPatch = memoOn<Pick<SurfaceState, 'secondNet'>, 'secondNet', PatchSamples>(
  ['secondNet'],
  ({ secondNet }) => samplePatch(secondNet),
);

const matrixOf = memoOn<SurfaceState, 'net' | 'u' | 'v' | 'coordinate', MatrixForm>(
  ['net', 'u', 'v', 'coordinate'],
  matrixForm,
);

/** The second patch and the join, in the scene of two patches; the box around what is drawn. */
const pairOf = memoOn<
  SurfaceState,
  'mode' | 'net' | 'secondNet',
  Pick<SurfaceModel, 'second' | 'join' | 'bounds'>
>(['mode', 'net', 'secondNet'], (state) => {
  const { net, secondNet } = state;
  const pair = state.mode === 'join';
  return {
    second: pair ? secondPatch(state) : null,
    join: pair ? joinReport(net, secondNet) : null,
    bounds: boundsOf(pair ? [...net.flat(), ...secondNet.flat()] : net.flat()),
  };
});

export function derive(state: SurfaceState, shown: Revealed<Reveal>): SurfaceModel {
  return {
    state,
    shown,
    patch: firstPatch(state),
    ...pairOf(state),
    ...atPoint(state),
    matrix: matrixOf(state),
  };
}

/**
 * The patch sampled along its iso-curves: for u fixed, the column points
 * c_n(u) are a cubic in v (the construction of the notes), sampled directly.
 */
function samplePatch(net: readonly (readonly Point[])[]): PatchSamples {
  const curve = (points: readonly Point[], segments: number): Point[] => {
    const flat = sampleBezier(points, segments);
    return Array.from({ length: segments + 1 }, (_, j) => [
      flat[3 * j],
      flat[3 * j + 1],
      flat[3 * j + 2],
    ]);
  };
  const grid: Point[][] = [];
  for (let i = 0; i <= FACETS; i++) grid.push(curve(surfaceColumnPoints(net, i / FACETS), FACETS));
  const uLines: Point[][] = [];
  const vLines: Point[][] = [];
  for (let i = 0; i <= ISO_LINES; i++) {
    uLines.push(curve(surfaceColumnPoints(net, i / ISO_LINES), CURVE_SEGMENTS));
    vLines.push(curve(surfaceRowPoints(net, i / ISO_LINES), CURVE_SEGMENTS));
  }
  const step = FACETS / ISO_LINES;
  const facetLines: Point[][] = [];
  for (let i = step; i < FACETS; i += step) {
    facetLines.push(grid[i]);
    facetLines.push(grid.map((row) => row[i]));
  }
  const facetEdges = [0, FACETS].flatMap((i) => [grid[i], grid.map((row) => row[i])]);
  return { grid, uLines, vLines, facetLines, facetEdges };
}

/** A cubic curve in 3D sampled at 33 points (drawn as a polyline in space). */
function sampleCurve(points: readonly Point[]): Point[] {
  const curve: Point[] = [];
  for (let j = 0; j <= CURVE_SEGMENTS; j++) {
    curve.push(bezierPoint(points, j / CURVE_SEGMENTS));
  }
  return curve;
}

function matrixForm(state: Pick<SurfaceState, 'net' | 'u' | 'v' | 'coordinate'>): MatrixForm {
  const d = coordinateIndex(state.coordinate);
  const M = bezierBasisMatrix(3);
  const powers = (t: number) => [1, t, t * t, t * t * t];
  const U = powers(state.u);
  const V = powers(state.v);
  const B = state.net.map((row) => row.map((p) => p[d]));
  const times = (row: readonly number[], matrix: readonly (readonly number[])[]) =>
    matrix[0].map((_, j) => row.reduce((sum, value, k) => sum + value * matrix[k][j], 0));
  const UM = times(U, M);
  const VM = times(V, M);
  const UMB = times(UM, B);
  return { U, V, M, B, UM, VM, UMB, value: UMB.reduce((sum, value, n) => sum + value * VM[n], 0) };
}

const ORDER: readonly Continuity[] = ['none', 'C0', 'G1', 'C1', 'G2', 'C2'];

export function joinReport(first: readonly Point[][], second: readonly Point[][]): JoinReport {
  const columns = first[0].map((_, n) =>
    bezierJointContinuity(
      first.map((row) => row[n]),
      second.map((row) => row[n]),
    ),
  );
  const weakest = columns.reduce((a, b) => (ORDER.indexOf(b) < ORDER.indexOf(a) ? b : a));
  return { columns, weakest };
}
