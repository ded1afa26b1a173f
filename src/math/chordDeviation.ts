import { bezierPoint } from './bezier';
import { checkInteger, checkNumber, checkPoints } from './validate';
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

/** The nearest point of segment a–b to p. */
export function nearestOnSegment(p: Point, a: Point, b: Point): Point {
  let along = 0;
  let length = 0;
  for (let d = 0; d < p.length; d++) {
    along += (p[d] - a[d]) * (b[d] - a[d]);
    length += (b[d] - a[d]) ** 2;
  }
  const s = length > 0 ? Math.min(1, Math.max(0, along / length)) : 0;
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
  let best: ChordDeviation | null = null;
  for (let k = 0; k + 1 < parameters.length; k++) {
    const t0 = parameters[k];
    const t1 = parameters[k + 1];
    const a = bezierPoint(points, t0);
    const b = bezierPoint(points, t1);
    const gap = (t: number) => {
      const p = bezierPoint(points, t);
      return distanceBetween(p, nearestOnSegment(p, a, b));
    };
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
    if (best === null || distance > best.distance) best = { distance, t, piece: k, point, foot };
  }
  return best as ChordDeviation;
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
 * The fewest uniform segments (parameters k / n) whose chords stay within
 * `tolerance` of the curve, searching n = 1 … `maximum`; `maximum` + 1 if none
 * of them does.
 */
export function uniformCountWithin(
  points: readonly Point[],
  tolerance: number,
  maximum = 512,
): number {
  checkNumber('uniformCountWithin', 'tolerance', tolerance);
  checkInteger('uniformCountWithin', 'maximum', maximum, 1);
  for (let n = 1; n <= maximum; n++) {
    if (chordDeviation(points, uniformParameters(n)).distance <= tolerance) return n;
  }
  return maximum + 1;
}
