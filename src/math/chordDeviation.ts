import { bezierDerivative, bezierPoint } from './bezier';
import { checkPoints } from './checkPoints';
import { checkInteger, checkNumber } from './validate';
import type { Point } from './vec';

// How far a curve strays from the polyline drawn for it. The polyline's
// vertices are curve points P(t0), P(t1), …, P(tm); piece k of the curve
// (t from tk to tk+1) is drawn as the chord from P(tk) to P(tk+1), and its
// deviation is the largest distance from a point of the piece to that chord.
// The largest over the pieces is the error a screen shows: flattening to a
// tolerance (flattenBezier) keeps it within the tolerance.

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

/** Where the nearest point of segment a–b to p lies along it: 0 at a, 1 at b (0 if a = b). */
function alongSegment(p: ArrayLike<number>, a: Point, b: Point): number {
  let along = 0;
  let length = 0;
  for (let d = 0; d < a.length; d++) {
    along += (p[d] - a[d]) * (b[d] - a[d]);
    length += (b[d] - a[d]) ** 2;
  }
  return length > 0 ? Math.min(1, Math.max(0, along / length)) : 0;
}

/** The nearest point of segment a–b to p. */
export function nearestOnSegment(p: Point, a: Point, b: Point): Point {
  const s = alongSegment(p, a, b);
  return a.map((value, d) => value + s * (b[d] - value));
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

/** The distance from p to segment a–b: nearestOnSegment and distanceBetween's arithmetic, without the arrays. */
function distanceToChord(p: ArrayLike<number>, a: Point, b: Point): number {
  const s = alongSegment(p, a, b);
  let squared = 0;
  for (let d = 0; d < a.length; d++) {
    const foot = a[d] + s * (b[d] - a[d]);
    squared += (p[d] - foot) ** 2;
  }
  return Math.sqrt(squared);
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

/** The parameters k / count, k = 0 … count: uniform sampling. */
export function uniformParameters(count: number): number[] {
  checkInteger('uniformParameters', 'count', count, 1);
  return Array.from({ length: count + 1 }, (_, k) => k / count);
}

/**
 * The uniform count the curvature asks for: a piece of parameter length h
 * strays about h²/8 · ‖P″⊥‖ from its chord (the second-order Taylor term; P″⊥
 * is the part of P″ across the tangent, as speeding up along a straight line
 * strays nowhere), so n uniform segments stray about max‖P″⊥‖ / (8n²), and
 * n ≈ √(max‖P″⊥‖ / (8·tolerance)), rounded up and at least 1. P′ and P″ are
 * sampled at 65 parameters of the hodographs. An estimate to start a search
 * from, not a guarantee.
 */
export function uniformCountEstimate(points: readonly Point[], tolerance: number): number {
  const caller = 'uniformCountEstimate';
  checkPoints(caller, 'points', points, 1);
  checkPositive(caller, tolerance);
  if (points.length < 3) return 1;
  const first = bezierDerivative(points);
  const second = bezierDerivative(first);
  let largest = 0;
  for (let i = 0; i <= 64; i++) {
    const velocity = bezierPoint(first, i / 64);
    const acceleration = bezierPoint(second, i / 64);
    let speed = 0;
    let along = 0;
    let size = 0;
    for (let d = 0; d < velocity.length; d++) {
      speed += velocity[d] ** 2;
      along += velocity[d] * acceleration[d];
      size += acceleration[d] ** 2;
    }
    // ‖P″⊥‖² = ‖P″‖² − (P′·P″)²/‖P′‖²; where the curve stops, P″ is its tangent.
    if (speed === 0) continue;
    const across = size - (along * along) / speed;
    largest = Math.max(largest, Math.sqrt(Math.max(0, across)));
  }
  return Math.max(1, Math.ceil(Math.sqrt(largest / (8 * tolerance))));
}

/**
 * A uniform count n ≤ `maximum` (parameters k / n) whose chords stay within
 * `tolerance` of the curve while those of n − 1 do not (or n = 1), found from
 * uniformCountEstimate by steps doubling away from it, then bisection: a few
 * chordDeviation calls, not one per count. Where the deviation falls as n
 * grows (it need not everywhere) this is the fewest. `maximum` + 1 when
 * `maximum` segments do not reach the tolerance either: more than `maximum`.
 */
export function uniformCountWithin(
  points: readonly Point[],
  tolerance: number,
  maximum = 512,
): number {
  checkNumber('uniformCountWithin', 'tolerance', tolerance);
  checkInteger('uniformCountWithin', 'maximum', maximum, 1);
  const within = (n: number) => chordDeviation(points, uniformParameters(n)).distance <= tolerance;
  // A tolerance of 0 (a straight curve's own gap) is only met by a straight piece.
  const guess =
    tolerance > 0 ? Math.min(maximum, uniformCountEstimate(points, tolerance)) : maximum;
  // `pass` reaches the tolerance, `fail` does not (0 segments never do).
  let pass: number;
  let fail = 0;
  if (within(guess)) {
    pass = guess;
    for (let step = 1; pass - step >= 1; step *= 2) {
      if (!within(pass - step)) {
        fail = pass - step;
        break;
      }
      pass -= step;
    }
  } else {
    fail = guess;
    for (let step = 1; ; step *= 2) {
      if (fail === maximum) return maximum + 1;
      const n = Math.min(maximum, fail + step);
      if (within(n)) {
        pass = n;
        break;
      }
      fail = n;
    }
  }
  while (pass - fail > 1) {
    const middle = Math.floor((pass + fail) / 2);
    if (within(middle)) pass = middle;
    else fail = middle;
  }
  return pass;
}

function checkPositive(caller: string, tolerance: number): void {
  checkNumber(caller, 'tolerance', tolerance);
  if (!(tolerance > 0)) {
    throw new RangeError(`${caller}: tolerance = ${tolerance}; it must be a positive distance.`);
  }
}
