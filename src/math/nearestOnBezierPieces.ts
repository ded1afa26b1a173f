import { evaluateBezier } from './bezier';
import { binomial } from './binomial';
import { checkPoint, checkPoints } from './checkPoints';
import type { Point } from './vec';

// The nearest point of a Bézier curve to Q (Schneider, "Solving the
// Nearest-Point-on-Curve Problem", Graphics Gems I, 1990): at the nearest
// interior point the chord to Q is perpendicular to the curve,
//   f(t) = (B(t) − Q) · B′(t) = 0,
// a polynomial of degree 2n − 1 whose Bernstein coefficients are products of
// those of B − Q (degree n) and B′ (degree n − 1):
//   c_k = Σ_{i+j=k} C(n,i) C(n−1,j) / C(2n−1,k) · (P_i − Q) · n(P_{j+1} − P_j).
// Its roots are found by subdividing the Bernstein form: a span whose
// coefficients never change sign holds no root (variation diminishing), so
// only spans near a root are split further. The nearest point is a root or
// an end. A chain of pieces is searched piece by piece, skipping every piece
// whose box of control points (which holds the piece) lies farther away than
// the best point found so far.

/** Where a chain of Bézier pieces comes nearest to a point. */
export interface NearestOnPieces {
  /** Index of the piece. */
  readonly piece: number;
  /** Parameter on that piece, in [0, 1]. */
  readonly t: number;
  /** The nearest point, `B_piece(t)`. */
  readonly point: Point;
  /** Its distance from the point asked about. */
  readonly distance: number;
}

export interface NearestOptions {
  /** The pieces' boxes from `bezierPieceBoxes` (computed once per chain), to skip far pieces. */
  readonly boxes?: Float64Array;
  /** Only points at most this far count; farther than this everywhere gives null. */
  readonly within?: number;
}

/**
 * The axis-aligned box of each piece's control points, `[min_0 … min_(d−1),
 * max_0 … max_(d−1)]` per piece in one array: a Bézier piece lies inside its
 * box (convex hull property), so a piece whose box is far away can be skipped.
 */
export function bezierPieceBoxes(pieces: readonly (readonly Point[])[]): Float64Array {
  const caller = 'bezierPieceBoxes';
  const dimension = pieces.length ? checkPoints(caller, 'pieces[0]', pieces[0], 1) : 0;
  const boxes = new Float64Array(2 * dimension * pieces.length);
  for (let index = 0; index < pieces.length; index++) {
    const piece = pieces[index];
    checkPiece(caller, pieces, index, dimension);
    const base = 2 * dimension * index;
    for (let d = 0; d < dimension; d++) {
      let low = piece[0][d];
      let high = low;
      for (let k = 1; k < piece.length; k++) {
        const value = piece[k][d];
        if (value < low) low = value;
        else if (value > high) high = value;
      }
      boxes[base + d] = low;
      boxes[base + dimension + d] = high;
    }
  }
  return boxes;
}

/**
 * The point of a chain of Bézier pieces (any degrees, one dimension) nearest
 * to `at`: its piece, parameter, position and distance. Ties go to the
 * earlier piece, then the smaller t (a joint is the end of the piece before
 * it). Null for no pieces, or when every point is farther than `within`.
 */
export function nearestOnBezierPieces(
  pieces: readonly (readonly Point[])[],
  at: Point,
  options: NearestOptions = {},
): NearestOnPieces | null {
  const caller = 'nearestOnBezierPieces';
  const dimension = checkPoint(caller, 'at', at);
  const { boxes, within = Infinity } = options;
  if (boxes && boxes.length !== 2 * dimension * pieces.length) {
    throw new RangeError(
      `${caller}: boxes has ${boxes.length} numbers but ${pieces.length} pieces in ${dimension}D need ${2 * dimension * pieces.length}; compute them with bezierPieceBoxes(pieces).`,
    );
  }
  let best: NearestOnPieces | null = null;
  let reach = within;
  const consider = (piece: number, t: number, point: Point) => {
    const distance = distanceBetween(point, at);
    if (distance > reach) return;
    if (
      best &&
      !(distance < best.distance || (distance === best.distance && earlier(piece, t, best)))
    )
      return;
    best = { piece, t, point: point.slice(), distance };
    reach = distance;
  };
  // A piece whose box is out of reach is passed over (bezierPieceBoxes has checked it).
  const outOfReach = (index: number) =>
    boxes !== undefined && boxDistance(boxes, index, at) > reach;
  // The ends of every piece first: a cheap first answer that lets most pieces be skipped.
  pieces.forEach((piece, index) => {
    if (outOfReach(index)) return;
    checkPiece(caller, pieces, index, dimension);
    consider(index, 0, piece[0]);
    consider(index, 1, piece[piece.length - 1]);
  });
  pieces.forEach((piece, index) => {
    if (piece.length < 2 || outOfReach(index)) return;
    for (const t of perpendicularFeet(piece, at))
      consider(index, t, evaluateBezier(piece, dimension, t));
  });
  return best;
}

/** checkPoints for pieces[index]; the name with its index is only built to word a failure. */
function checkPiece(
  caller: string,
  pieces: readonly (readonly Point[])[],
  index: number,
  dimension: number,
): void {
  try {
    checkPoints(caller, 'a piece', pieces[index], 1, dimension);
  } catch {
    checkPoints(caller, `pieces[${index}]`, pieces[index], 1, dimension);
  }
}

const earlier = (piece: number, t: number, than: NearestOnPieces) =>
  piece < than.piece || (piece === than.piece && t < than.t);

function distanceBetween(a: Point, b: Point): number {
  let squared = 0;
  for (let d = 0; d < b.length; d++) squared += (a[d] - b[d]) ** 2;
  return Math.sqrt(squared);
}

/** Distance from `at` to the box of piece `index` (0 inside it). */
function boxDistance(boxes: Float64Array, index: number, at: Point): number {
  const dimension = at.length;
  const base = 2 * dimension * index;
  let squared = 0;
  for (let d = 0; d < dimension; d++) {
    const below = boxes[base + d] - at[d];
    const above = at[d] - boxes[base + dimension + d];
    const outside = Math.max(below, above, 0);
    squared += outside * outside;
  }
  return Math.sqrt(squared);
}

/** Bernstein weights C(n,i) C(n−1,j) / C(2n−1,i+j), per degree n, row i, column j. */
const weightsByDegree = new Map<number, Float64Array>();

function productWeights(n: number): Float64Array {
  let weights = weightsByDegree.get(n);
  if (!weights) {
    weights = new Float64Array((n + 1) * n);
    for (let i = 0; i <= n; i++)
      for (let j = 0; j < n; j++)
        weights[i * n + j] = (binomial(n, i) * binomial(n - 1, j)) / binomial(2 * n - 1, i + j);
    weightsByDegree.set(n, weights);
  }
  return weights;
}

/** Spans narrower than this (in t) are not split further: the root is placed by the chord. */
const NARROWEST = 2 ** -40;

/** Parameters in [0, 1] where (B(t) − at) · B′(t) changes sign: the feet of perpendiculars from `at`. */
function perpendicularFeet(piece: readonly Point[], at: Point): number[] {
  const n = piece.length - 1;
  const weights = productWeights(n);
  const coefficients = new Float64Array(2 * n);
  for (let i = 0; i <= n; i++) {
    for (let j = 0; j < n; j++) {
      let product = 0;
      for (let d = 0; d < at.length; d++)
        product += (piece[i][d] - at[d]) * n * (piece[j + 1][d] - piece[j][d]);
      coefficients[i + j] += weights[i * n + j] * product;
    }
  }
  const feet: number[] = [];
  findRoots(coefficients, 0, 1, feet);
  return feet;
}

/** Collects into `roots` the sign changes of the Bernstein polynomial `c` on [t0, t1]. */
function findRoots(c: Float64Array, t0: number, t1: number, roots: number[]): void {
  const last = c.length - 1;
  if (c[0] === 0) roots.push(t0);
  if (c[last] === 0) roots.push(t1);
  if (signChanges(c) === 0) return;
  if (t1 - t0 <= NARROWEST) {
    const opposite = c[0] * c[last] < 0;
    roots.push(opposite ? t0 + ((t1 - t0) * c[0]) / (c[0] - c[last]) : (t0 + t1) / 2);
    return;
  }
  // de Casteljau at ½: the left half's coefficients run down the first
  // column of the triangle, the right half's up its last diagonal.
  const left = new Float64Array(c.length);
  const right = new Float64Array(c.length);
  const row = c.slice();
  for (let r = 0; r <= last; r++) {
    left[r] = row[0];
    right[last - r] = row[last - r];
    for (let i = 0; i < last - r; i++) row[i] = (row[i] + row[i + 1]) / 2;
  }
  const middle = (t0 + t1) / 2;
  findRoots(left, t0, middle, roots);
  findRoots(right, middle, t1, roots);
}

/** Sign changes in the sequence, zeros skipped. */
function signChanges(c: Float64Array): number {
  let changes = 0;
  let sign = 0;
  for (const value of c) {
    if (value === 0) continue;
    const s = value > 0 ? 1 : -1;
    if (sign !== 0 && s !== sign) changes++;
    sign = s;
  }
  return changes;
}
