import { type Point, bezierPieceBoxes, bezierPoint } from '../../math';
import { LABEL_VILLAGES } from './points';
import { type CurvatureComb, curvatureComb, parameterTicks } from './roadMarks';
import { type Road, asCubics } from './roads';
import { type SolveProgress, builtPieces } from './solve';
import { type RoadState, segmentCount } from './state';

/**
 * Up to this many segments the ticks of p̄ are worked out (and drawn): beyond,
 * a segment is too short on the map for its quarters to be told apart (50
 * villages: 26 px in presenter view, a tick every 6 px), and the villages'
 * dots mark where each segment begins.
 */
const TICK_SEGMENTS = LABEL_VILLAGES;

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

/** The piece and local parameter p of the global p̄ on a road of `count` pieces. */
export function localParameter(s: number, count: number): { piece: number; p: number } {
  const piece = Math.max(0, Math.min(Math.floor(s), count - 1));
  return { piece, p: s - piece };
}

/**
 * The method's road on the map, with what is drawn along it and what the
 * pointer can find on it; while the solve runs (`progress`), the pieces built so far.
 */
export function showRoad(
  state: RoadState,
  road: Road,
  gradients: Point[] | undefined,
  progress: SolveProgress | null,
  span: number,
  /** Without a solve under way: how many pieces are built so far, from P0. */
  limit = Infinity,
): ShownRoad {
  const all = road.kind === 'pieces' ? road.pieces : [];
  const pieces = progress
    ? builtPieces(state.villages, gradients!, progress)
    : limit < all.length
      ? all.slice(0, limit)
      : all;
  const built = !progress && pieces.length > 0 && pieces.length === all.length;
  const marker = built ? localParameter(state.pBar, pieces.length) : null;
  return {
    pieces,
    cubics: asCubics(pieces),
    boxes: bezierPieceBoxes(pieces),
    offset: progress ? segmentCount(state) - pieces.length : 0,
    missing: road.kind === 'missing' ? road.why : null,
    marker: marker && { ...marker, point: bezierPoint(pieces[marker.piece], marker.p) },
    ticks: built && pieces.length <= TICK_SEGMENTS ? parameterTicks(pieces) : null,
    // Teeth as long as the curvature times a tenth of the map; fewer of them on a long road.
    comb: state.comb ? curvatureComb(pieces, span / 10, pieces.length > 100 ? 6 : 16) : null,
  };
}
