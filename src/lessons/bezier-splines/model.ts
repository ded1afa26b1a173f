import {
  bezierChainSelfIntersections,
  bezierDerivative,
  bezierJointReport,
  bezierPoint,
  catmullRomSegments,
  catmullRomTangents,
  controlPointName,
  cubicSplineC2,
  cubicSplineSegments,
  elevateDegree,
  onOneSpot,
  sampleBezier,
  type JointReport,
  type Point,
  quadraticSplineC1,
  solveCubicSplineC2System,
  type SplineSystemSolution,
} from '../../math';
import { type BezierSplinesState, handTangents, midpoint } from './state';

export type Dataset = 'inf' | 'spi' | 'semi';
export const DATASETS: readonly Dataset[] = ['inf', 'spi', 'semi'];

/** One row of the 3 × 3 figure: a dataset drawn as C⁰, C¹ and C² splines. */
export interface GridRow {
  points: Point[];
  /** The polygon through the points (cubic pieces with control points on the chords). */
  c0: Point[][];
  /** The C¹ quadratic spline, b0 the midpoint of p0p1. */
  c1: Point[][];
  c2: Point[][];
}

/** A tooth of the curvature comb: from the curve, along the normal, as long as the curvature. */
export type Tooth = [Point, Point];

export interface BezierSplinesModel {
  state: BezierSplinesState;
  /** Part 1: the one Bézier curve with the points as control points, and with one point moved. */
  moved: number;
  movedPoints: Point[];
  single: Float64Array;
  singleMoved: Float64Array;
  spline: Point[][];
  movedSpline: Point[][];
  /** Part 2: the quadratic pieces (raised to degree 3 to draw) and their control points b0 … b(n−1). */
  quadratic: Point[][];
  quadraticControls: Point[];
  /** b0 moved by ±δ: the whole spline swings. */
  swing: [Point[][], Point[][]];
  /** Part 3: the (3n+1) system solved, its control points' names, the natural spline, their difference. */
  system: SplineSystemSolution;
  names: string[];
  natural: Point[][];
  difference: number;
  /** Part 4: the practical's three datasets. */
  grid: Record<Dataset, GridRow>;
  /** Part 5: the hand-built pieces, the report at each inner joint, the comb. */
  pieces: Point[][];
  joints: JointReport[];
  comb: Tooth[];
  /** Part 6: Hermite with hand tangents, Catmull-Rom tangents, the α splines and their crossings. */
  hermite: Point[][];
  crTangents: Point[];
  oneSided: Point[][];
  oneSidedTangents: Point[];
  alphas: { alpha: number; name: string; segments: Point[][]; crossings: Point[] }[];
  /** The points the figure starts from are all on one spot (the figure says what that makes). */
  oneSpot: boolean;
}

export const SWING = 0.5;

export function derive(state: BezierSplinesState): BezierSplinesModel {
  const { p } = state;
  const moved = Math.floor(p.length / 2);
  const movedPoints = p.map((q, i) => (i === moved ? [q[0], q[1] + 1] : q));
  const quadratic = quadraticSplineC1(p, state.b[0]);
  const b0 = state.b[0];
  const system = solveCubicSplineC2System(p);
  const natural = cubicSplineC2(p);
  let difference = 0;
  natural.forEach((segment, i) =>
    segment.forEach((q, k) =>
      q.forEach((v, d) => {
        difference = Math.max(difference, Math.abs(v - system.controls[3 * i + k][d]));
      }),
    ),
  );
  const pieces = piecesOf(state.q);
  const crTangents = catmullRomTangents(p);
  const oneSidedTangents = crTangents.map((t, i) =>
    i === 0 ? sub(p[1], p[0]) : i === p.length - 1 ? sub(p[i], p[i - 1]) : t,
  );
  const catmull = state.part === 'catmull';
  return {
    state,
    oneSpot: onOneSpot(state.part === 'inspector' ? state.q : p),
    moved,
    movedPoints,
    single: sampleBezier(p, 200),
    singleMoved: sampleBezier(movedPoints, 200),
    spline: natural,
    movedSpline: cubicSplineC2(movedPoints),
    quadratic: quadratic.map(asCubic),
    quadraticControls: quadratic.map((segment) => segment[1]),
    swing: [
      quadraticSplineC1(p, [b0[0], b0[1] + SWING]).map(asCubic),
      quadraticSplineC1(p, [b0[0], b0[1] - SWING]).map(asCubic),
    ],
    system,
    names: system.controls.map((_, j) => controlPointName(j, system.controls.length)),
    natural,
    difference,
    grid: {
      inf: gridRow(state.inf),
      spi: gridRow(state.spi),
      semi: gridRow(state.semi),
    },
    pieces,
    joints: pieces.slice(1).map((piece, k) => bezierJointReport(pieces[k], piece)),
    comb: comb(pieces),
    // A state straight from a scene may not have one tangent per point yet (normalize adds them).
    hermite: cubicSplineSegments(p, state.tg.length === p.length ? state.tg : handTangents(p)),
    crTangents,
    oneSided: cubicSplineSegments(p, oneSidedTangents),
    oneSidedTangents,
    alphas: [
      [0, 'uniform'],
      [0.5, 'centripetal'],
      [1, 'chordal'],
    ].map(([alpha, name]) => {
      const segments = catmullRomSegments(p, alpha as number);
      // Crossings are only looked for where they are shown.
      return {
        alpha: alpha as number,
        name: name as string,
        segments,
        crossings: catmull ? bezierChainSelfIntersections(segments) : [],
      };
    }),
  };
}

const sub = (a: Point, b: Point): Point => [a[0] - b[0], a[1] - b[1]];

/** A line or quadratic piece as the same curve of degree 3 (to draw all pieces alike). */
export function asCubic(segment: Point[]): Point[] {
  let result = segment;
  while (result.length < 4) result = elevateDegree(result);
  return result;
}

/** Control points c0 … c3k as k cubic pieces. */
export const piecesOf = (q: readonly Point[]): Point[][] =>
  Array.from({ length: Math.floor((q.length - 1) / 3) }, (_, k) => q.slice(3 * k, 3 * k + 4));

function gridRow(points: Point[]): GridRow {
  return {
    points,
    c0: points.slice(1).map((next, i) => asCubic([points[i], next])),
    c1: quadraticSplineC1(points, midpoint(points[0], points[1])).map(asCubic),
    c2: cubicSplineC2(points),
  };
}

/** Teeth along every piece, scaled so the longest is an eighth of the spline's size. */
function comb(pieces: readonly Point[][]): Tooth[] {
  const raw: { at: Point; normal: Point; kappa: number }[] = [];
  for (const piece of pieces) {
    const first = bezierDerivative(piece);
    const second = bezierDerivative(first);
    for (let k = 0; k <= 16; k++) {
      const t = k / 16;
      const [dx, dy] = bezierPoint(first, t);
      const [ex, ey] = bezierPoint(second, t);
      const speed = Math.hypot(dx, dy);
      if (!(speed > 1e-9)) continue;
      const kappa = (dx * ey - dy * ex) / speed ** 3;
      raw.push({ at: bezierPoint(piece, t), normal: [-dy / speed, dx / speed], kappa });
    }
  }
  const xs = pieces.flat().map((q) => q[0]);
  const ys = pieces.flat().map((q) => q[1]);
  const size = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys), 1e-9);
  const largest = Math.max(...raw.map((r) => Math.abs(r.kappa)), 1e-9);
  const factor = (0.125 * size) / largest;
  // The comb points away from the centre of curvature, as CAD systems draw it.
  return raw.map(({ at, normal, kappa }) => [
    at,
    [at[0] - normal[0] * kappa * factor, at[1] - normal[1] * kappa * factor],
  ]);
}
