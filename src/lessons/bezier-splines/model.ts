import {
  bezierChainSelfIntersections,
  bezierJointReport,
  catmullRomSegments,
  catmullRomTangents,
  controlPointName,
  cubicSplineC2,
  cubicSplineSegments,
  onOneSpot,
  sampleBezier,
  type JointReport,
  type Point,
  quadraticSplineC1,
  solveCubicSplineC2System,
  type SplineSystemSolution,
} from '../../math';
import { memoOn } from '../../kit/memoOn';
import type { Revealed } from '../../kit/script';
import { asCubic, comb, loopBounds, piecesOf, type Tooth } from './pieces';
import { type Bounds, boundsOf, diagonal } from '../../render/projection';
import type { Reveal } from './script';
import { type BezierSplinesState, handTangents, midpoint } from './state';
import { type HandC1, type HandC2, continuation, handC1, handC2 } from './workedExample';

export { asCubic, piecesOf, type Tooth } from './pieces';

/** The practical's three datasets, by their field in the state. */
export type Dataset = 'infinity' | 'spiral' | 'semicircle';
export const DATASETS: readonly Dataset[] = ['infinity', 'spiral', 'semicircle'];

/** One row of the 3 × 3 figure: a dataset drawn as C⁰, C¹ and C² splines. */
export interface GridRow {
  points: Point[];
  /** The polygon through the points (cubic pieces with control points on the chords). */
  c0: Point[][];
  /** The C¹ quadratic spline, b0 the midpoint of p0p1. */
  c1: Point[][];
  c2: Point[][];
}

export interface BezierSplinesModel {
  state: BezierSplinesState;
  /** What the current part's steps so far reveal. */
  shown: Revealed<Reveal>;
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
  alphas: {
    alpha: number;
    name: string;
    segments: Point[][];
    crossings: Point[];
    /** Where the curve loops through its first crossing (the inset magnifies it), or null. */
    loop: Bounds | null;
  }[];
  /** Part 7: the practical's computeSplineC1 and computeSplineC2 worked by hand. */
  worked: { c1: HandC1; c2: HandC2 };
  /** Part 8: the points as splines of degree 1, 2 and 3, and the first cubic piece continued past its end. */
  degree: { row: GridRow; continued: Point[] };
  /** The points the figure starts from are all on one spot (the figure says what that makes). */
  oneSpot: boolean;
}

export const SWING = 0.5;

type State = BezierSplinesState;

// Each part's geometry is kept while the fields it reads are the same: a
// clicker press (a new step) solves no spline again.

/** Part 1: one Bézier curve through all the points against the C² pieces, and p_m moved up by 1. */
const whyPieces = memoOn<
  State,
  'points',
  Pick<BezierSplinesModel, 'moved' | 'movedPoints' | 'single' | 'singleMoved' | 'movedSpline'>
>(['points'], ({ points: p }) => {
  const moved = Math.floor(p.length / 2);
  const movedPoints = p.map((q, i) => (i === moved ? [q[0], q[1] + 1] : q));
  return {
    moved,
    movedPoints,
    single: sampleBezier(p, 200),
    singleMoved: sampleBezier(movedPoints, 200),
    movedSpline: cubicSplineC2(movedPoints),
  };
});

/** Part 2: the C¹ quadratic spline from b0, and from b0 ± δ. */
const quadraticPieces = memoOn<
  State,
  'points' | 'firstControl',
  Pick<BezierSplinesModel, 'quadratic' | 'quadraticControls' | 'swing'>
>(['points', 'firstControl'], ({ points: p, firstControl: [b0] }) => {
  const quadratic = quadraticSplineC1(p, b0);
  return {
    quadratic: quadratic.map(asCubic),
    quadraticControls: quadratic.map((segment) => segment[1]),
    swing: [
      quadraticSplineC1(p, [b0[0], b0[1] + SWING]).map(asCubic),
      quadraticSplineC1(p, [b0[0], b0[1] - SWING]).map(asCubic),
    ],
  };
});

/** Part 3: the (3n+1) system solved, against the natural cubic spline (also part 1's C² pieces). */
const systemPieces = memoOn<
  State,
  'points',
  Pick<BezierSplinesModel, 'system' | 'names' | 'natural' | 'difference'>
>(['points'], ({ points: p }) => {
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
  const names = system.controls.map((_, j) => controlPointName(j, system.controls.length));
  return { system, names, natural, difference };
});

/** Part 4: one memo per dataset, so dragging in one row leaves the others alone. */
const gridRows = Object.fromEntries(
  DATASETS.map((dataset) => [
    dataset,
    memoOn<State, Dataset, GridRow>([dataset], (fields) => gridRow(fields[dataset])),
  ]),
) as Record<Dataset, (state: State) => GridRow>;

/** Part 5: the hand-built pieces, the report at each inner joint, the comb. */
const inspectorPieces = memoOn<
  State,
  'handBuilt',
  Pick<BezierSplinesModel, 'pieces' | 'joints' | 'comb'>
>(['handBuilt'], ({ handBuilt }) => {
  const pieces = piecesOf(handBuilt);
  return {
    pieces,
    joints: pieces.slice(1).map((piece, k) => bezierJointReport(pieces[k], piece)),
    comb: comb(pieces),
  };
});

/** Part 6: Hermite with hand tangents, Catmull-Rom's tangents, the three α splines. */
const catmullPieces = memoOn<
  State,
  'points' | 'tangents' | 'part',
  Pick<BezierSplinesModel, 'hermite' | 'crTangents' | 'oneSided' | 'oneSidedTangents' | 'alphas'>
>(['points', 'tangents', 'part'], ({ points: p, tangents, part }) => {
  const crTangents = catmullRomTangents(p);
  const oneSidedTangents = crTangents.map((t, i) =>
    i === 0 ? sub(p[1], p[0]) : i === p.length - 1 ? sub(p[i], p[i - 1]) : t,
  );
  return {
    // A state straight from a scene may not have one tangent per point yet (normalize adds them).
    hermite: cubicSplineSegments(p, tangents.length === p.length ? tangents : handTangents(p)),
    crTangents,
    oneSided: cubicSplineSegments(p, oneSidedTangents),
    oneSidedTangents,
    alphas: (
      [
        [0, 'uniform'],
        [0.5, 'centripetal'],
        [1, 'chordal'],
      ] as const
    ).map(([alpha, name]) => {
      const segments = catmullRomSegments(p, alpha);
      // Crossings are only looked for where they are shown.
      const crossings = part === 'catmull' ? bezierChainSelfIntersections(segments) : [];
      const loop = crossings.length
        ? loopBounds(segments, crossings[0], LOOP_NEAR * diagonal(boundsOf(p)))
        : null;
      return { alpha, name, segments, crossings, loop };
    }),
  };
});

/** Parts 7 and 8: the hand computations, the three degrees, the first cubic continued. */
const workedPieces = memoOn<State, 'points', Pick<BezierSplinesModel, 'worked' | 'degree'>>(
  ['points'],
  ({ points: p }) => {
    const c2 = handC2(p);
    return {
      worked: { c1: handC1(p), c2 },
      degree: { row: gridRow(p), continued: continuation(c2.controls.slice(0, 4)) },
    };
  },
);

/** Everything the figures and the panel show, with what the current step reveals. */
export function derive(state: State, shown: Revealed<Reveal>): BezierSplinesModel {
  const system = systemPieces(state);
  return {
    state,
    shown,
    oneSpot: onOneSpot(state.part === 'inspector' ? state.handBuilt : state.points),
    ...whyPieces(state),
    spline: system.natural,
    ...quadraticPieces(state),
    ...system,
    grid: {
      infinity: gridRows.infinity(state),
      spiral: gridRows.spiral(state),
      semicircle: gridRows.semicircle(state),
    },
    ...inspectorPieces(state),
    ...catmullPieces(state),
    ...workedPieces(state),
  };
}

const sub = (a: Point, b: Point): Point => [a[0] - b[0], a[1] - b[1]];

function gridRow(points: Point[]): GridRow {
  return {
    points,
    c0: points.slice(1).map((next, i) => asCubic([points[i], next])),
    c1: quadraticSplineC1(points, midpoint(points[0], points[1])).map(asCubic),
    c2: cubicSplineC2(points),
  };
}

/** A pass through a crossing: within this share of the points' diagonal of it. */
const LOOP_NEAR = 0.02;
