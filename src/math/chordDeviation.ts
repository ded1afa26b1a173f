import { bezierPoint } from './bezier';
import { checkPoints } from './checkPoints';
import { distanceToChord, nearestOnSegment } from './nearestOnSegment';
import { checkInteger, checkNumber } from './validate';
import type { Point } from './vec';

// How far a curve strays from the polyline drawn for it. The polyline's
// vertices are curve points P(t0), P(t1), …, P(tm); piece k of the curve
// (t from tk to tk+1) is drawn as the chord from P(tk) to P(tk+1), and its
// deviation is the largest distance from a point of the piece to that chord.
// The largest over the pieces is the error a screen shows: flattening to a
// tolerance (flattenBezier) keeps it within the tolerance.
// uniformCount.ts finds how many uniform pieces keep it within a tolerance.

/** Where the curve is farthest from the chord drawn for its piece, and how far. */
export interface ChordDeviation {
  /** The largest distance from a curve point to the chord of its piece. */
  distance: number;
  /** The parameter of that curve point. */
  t: number;
  /** The index k of the piece (t from parameters[k] to parameters[k + 1]). */
  piece: number;
  /** The curve point P(t). */
  point: Point;
  /** The nearest point of the chord to P(t). */
  foot: Point;
}

function distanceBetween(p: Point, q: Point): number {
  let squared = 0;
  for (let d = 0; d < p.length; d++) squared += (p[d] - q[d]) ** 2;
  return Math.sqrt(squared);
}

/**
 * The deviation of the polyline through P(t0), …, P(tm) from the Bézier curve
 * of `points`: every piece sampled at `samples` + 1 parameters, the largest
 * distance refined by golden-section search between the neighbouring samples
 * (to about 1e-10 in t, so the distance is exact to rounding where the
 * maximum is smooth). `parameters` must increase from 0 to 1 or any sub-range.
 */
export function chordDeviation(
  points: readonly Point[],
  parameters: readonly number[],
  samples = 32,
): ChordDeviation {
  const caller = 'chordDeviation';
  checkPoints(caller, 'points', points, 1);
  checkInteger(caller, 'samples', samples, 2);
  if (parameters.length < 2) {
    throw new RangeError(
      `${caller}: parameters has ${parameters.length} values; it needs at least 2.`,
    );
  }
  for (let k = 0; k < parameters.length; k++) {
    checkNumber(caller, `parameters[${k}]`, parameters[k]);
    if (k > 0 && !(parameters[k] > parameters[k - 1])) {
      throw new RangeError(
        `${caller}: parameters must increase; parameters[${k}] = ${parameters[k]}.`,
      );
    }
  }
  const curve = curveEvaluator(points);
  // Branch and bound: a piece cannot stray further than its control points,
  // so pieces are measured from the largest bound down and the rest skipped
  // once the largest gap found exceeds their bounds (with a margin for
  // rounding). The result is the one measuring every piece in order gives.
  const bounds = parameters.slice(1).map((t1, k) => pieceHullGap(points, parameters[k], t1));
  const order = bounds.map((_, k) => k).sort((i, j) => bounds[j] - bounds[i] || i - j);
  // Rounding in the gaps is of the order of 1e-16 of the coordinates.
  let slack = 0;
  for (const p of points) for (const v of p) slack = Math.max(slack, 1e-12 * Math.abs(v));
  let best: ChordDeviation | null = null;
  for (const k of order) {
    if (best !== null && bounds[k] * (1 + 1e-7) + slack < best.distance) break;
    const t0 = parameters[k];
    const t1 = parameters[k + 1];
    const a = bezierPoint(points, t0);
    const b = bezierPoint(points, t1);
    const gap = (t: number) => distanceToChord(curve(t), a, b);
    let bestIndex = 0;
    let bestGap = -1;
    for (let i = 0; i <= samples; i++) {
      const value = gap(t0 + ((t1 - t0) * i) / samples);
      if (value > bestGap) {
        bestGap = value;
        bestIndex = i;
      }
    }
    const t = refineMaximum(
      gap,
      t0 + ((t1 - t0) * Math.max(0, bestIndex - 1)) / samples,
      t0 + ((t1 - t0) * Math.min(samples, bestIndex + 1)) / samples,
    );
    const point = bezierPoint(points, t);
    const foot = nearestOnSegment(point, a, b);
    const distance = distanceBetween(point, foot);
    const better =
      best === null || distance > best.distance || (distance === best.distance && k < best.piece);
    if (better) best = { distance, t, piece: k, point, foot };
  }
  return best as ChordDeviation;
}

/**
 * The largest distance from a control point of the piece t0 … t1 to its
 * chord Q0–Qn (Q by de Casteljau at t1, then at t0/t1 on the left part). The
 * piece lies in the convex hull of Q, and the distance to a segment is convex,
 * so no point of the piece is further from the chord than this.
 */
function pieceHullGap(points: readonly Point[], t0: number, t1: number): number {
  const count = points.length;
  const n = count - 1;
  const dimension = points[0].length;
  const piece = new Float64Array(count * dimension);
  const row = new Float64Array(count);
  const u = t0 / t1;
  for (let d = 0; d < dimension; d++) {
    for (let i = 0; i < count; i++) row[i] = points[i][d];
    // Left part at t1: the first point of every level.
    const left = new Float64Array(count);
    left[0] = row[0];
    for (let r = 1; r <= n; r++) {
      for (let i = 0; i + r <= n; i++) row[i] = (1 - t1) * row[i] + t1 * row[i + 1];
      left[r] = row[0];
    }
    // Right part of that at u: the last point of every level.
    row.set(left);
    piece[d * count + n] = row[n];
    for (let r = 1; r <= n; r++) {
      for (let i = 0; i + r <= n; i++) row[i] = (1 - u) * row[i] + u * row[i + 1];
      piece[d * count + n - r] = row[n - r];
    }
  }
  const a = Array.from({ length: dimension }, (_, d) => piece[d * count]);
  const b = Array.from({ length: dimension }, (_, d) => piece[d * count + n]);
  const q = new Float64Array(dimension);
  let largest = 0;
  for (let i = 1; i < n; i++) {
    for (let d = 0; d < dimension; d++) q[d] = piece[d * count + i];
    largest = Math.max(largest, distanceToChord(q, a, b));
  }
  return largest;
}

/**
 * P(t) for many t without an allocation each: de Casteljau's interpolations
 * (the same, in the same order, as bezierPoint's) on one scratch row, into one
 * reused vector. The search evaluates the curve ~90 times per piece, so this
 * is most of chordDeviation's time.
 */
function curveEvaluator(points: readonly Point[]): (t: number) => Float64Array {
  const count = points.length;
  const dimension = points[0].length;
  const coordinates = new Float64Array(count * dimension);
  for (let i = 0; i < count; i++)
    for (let d = 0; d < dimension; d++) coordinates[d * count + i] = points[i][d];
  const row = new Float64Array(count);
  const result = new Float64Array(dimension);
  return (t) => {
    const s = 1 - t;
    for (let d = 0; d < dimension; d++) {
      for (let i = 0; i < count; i++) row[i] = coordinates[d * count + i];
      for (let r = count - 1; r > 0; r--)
        for (let i = 0; i < r; i++) row[i] = s * row[i] + t * row[i + 1];
      result[d] = row[0];
    }
    return result;
  };
}

const GOLDEN = (Math.sqrt(5) - 1) / 2;

/** The parameter of the largest value of `f` on [low, high] (golden-section search, f unimodal there). */
function refineMaximum(f: (t: number) => number, low: number, high: number): number {
  let a = low;
  let b = high;
  let c = b - GOLDEN * (b - a);
  let d = a + GOLDEN * (b - a);
  let fc = f(c);
  let fd = f(d);
  for (let i = 0; i < 80 && b - a > 1e-12; i++) {
    if (fc > fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - GOLDEN * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + GOLDEN * (b - a);
      fd = f(d);
    }
  }
  const middle = (a + b) / 2;
  // The end points of the bracket can be larger (a maximum at the bracket's edge).
  return [low, middle, high].reduce((x, y) => (f(y) > f(x) ? y : x));
}
