import {
  type ChordDeviation,
  type FlatteningNode,
  type Point,
  bezierPoint,
  chordDeviation,
  flatteningTree,
  nearestOnSegment,
  uniformCountWithin,
  uniformParameters,
} from '../../math';

/** A polyline drawn for the curve: its vertices P(tk) and how far the curve strays from it. */
export interface Polyline {
  parameters: number[];
  points: Point[];
  /** In units of the control points (pixels at zoom 1). */
  deviation: ChordDeviation;
}

/** Uniform segments the compare scene searches up to; past it the lesson says "more than". */
export const SAME_ERROR_MAX = 512;

/** Samples per piece of the gap function. */
const GAP_SAMPLES = 24;

/** The polyline through P(t) at these parameters. */
export function polyline(points: readonly Point[], parameters: number[]): Polyline {
  return {
    parameters,
    points: parameters.map((t) => bezierPoint(points, t)),
    deviation: chordDeviation(points, parameters),
  };
}

/** (t, distance from P(t) to the chord of its piece) over every piece. */
export function gapFunction(points: readonly Point[], line: Polyline): Float64Array {
  const pieces = line.parameters.length - 1;
  const gaps = new Float64Array(2 * (pieces * GAP_SAMPLES + 1));
  let at = 0;
  for (let piece = 0; piece < pieces; piece++) {
    const [t0, t1] = [line.parameters[piece], line.parameters[piece + 1]];
    // Each piece after the first starts where the one before ended.
    for (let s = piece === 0 ? 0 : 1; s <= GAP_SAMPLES; s++) {
      const t = t0 + ((t1 - t0) * s) / GAP_SAMPLES;
      const p = bezierPoint(points, t);
      const q = nearestOnSegment(p, line.points[piece], line.points[piece + 1]);
      gaps[at++] = t;
      gaps[at++] = Math.hypot(p[0] - q[0], p[1] - q[1]);
    }
  }
  return gaps;
}

/** The flattening's leaves as parameters t0 = 0 < t1 < … < tm = 1. */
const leafParameters = (tree: readonly FlatteningNode[]) => [
  0,
  ...tree.filter((node) => !node.split).map((node) => node.t1),
];

/** Adaptive flattening to `tolerance` (units): every piece it looked at, and its polyline. */
export function adaptiveAt(points: readonly Point[], tolerance: number) {
  const tree = flatteningTree(points, tolerance);
  const adaptive = polyline(points, leafParameters(tree));
  // The drawn vertices are the leaves' end points: flattenBezier's polyline,
  // point for point, without flattening a second time.
  const leaves = tree.filter((node) => !node.split);
  adaptive.points = [
    tree[0].points[0],
    ...leaves.map((node) => node.points[node.points.length - 1]),
  ];
  return { tree, adaptive };
}

/** Uniform sampling as good as adaptive flattening (the compare scene; elsewhere null, false). */
export interface SameGap {
  /** The fewest uniform segments with at most the adaptive polyline's gap; null past SAME_ERROR_MAX. */
  sameError: Polyline | null;
  /** Uniform sampling would need more than SAME_ERROR_MAX segments (so none is drawn). */
  sameErrorBeyond: boolean;
}

/** The fewest uniform segments whose polyline strays at most `gap` (the search stops at SAME_ERROR_MAX). */
export function sameGap(points: readonly Point[], gap: number): SameGap {
  const count = uniformCountWithin(points, gap, SAME_ERROR_MAX);
  if (count > SAME_ERROR_MAX) return { sameError: null, sameErrorBeyond: true };
  return { sameError: polyline(points, uniformParameters(count)), sameErrorBeyond: false };
}
