import { texNumber } from '../../kit/format';

// The basis functions on equally spaced knots, written out as polynomials in
// the local parameter t of one knot span: row r of Cox–de Boor done by hand.
// Row 3 gives the continuation notes' uniform cubic bases B0(t) … B3(t).

/** A polynomial in t by its integer coefficients, lowest power first, over a denominator. */
export interface Piece {
  /** Coefficients of 1, t, t², … of r!·N (whole numbers). */
  coefficients: number[];
  /** r!, the denominator. */
  denominator: number;
}

/** (a + b·t)·p: a polynomial times a linear factor. */
function timesLinear(p: readonly number[], a: number, b: number): number[] {
  const out = Array.from({ length: p.length + 1 }, () => 0);
  p.forEach((c, k) => {
    out[k] += a * c;
    out[k + 1] += b * c;
  });
  return out;
}

const add = (p: readonly number[], q: readonly number[]) =>
  Array.from({ length: Math.max(p.length, q.length) }, (_, k) => (p[k] ?? 0) + (q[k] ?? 0));

/**
 * The r + 1 pieces of row r on one span [u_j, u_j + h) of equally spaced
 * knots, with t = (u − u_j)/h: piece k is N_{j−r+k, r}. Cox–de Boor with
 * (u − u_i)/(r·h) = (t + r − k)/r and (u_{i+r+1} − u)/(r·h) = (k + 1 − t)/r:
 * r!·N_{r,k} = (t + r − k)·(r−1)!·N_{r−1,k−1} + (k + 1 − t)·(r−1)!·N_{r−1,k}.
 */
export function uniformPieces(r: number): Piece[] {
  let row: number[][] = [[1]];
  let denominator = 1;
  for (let q = 1; q <= r; q++) {
    row = Array.from({ length: q + 1 }, (_, k) => {
      const rising = k > 0 ? timesLinear(row[k - 1], q - k, 1) : [0];
      const falling = k < q ? timesLinear(row[k], k + 1, -1) : [0];
      return add(rising, falling);
    });
    denominator *= q;
  }
  return row.map((coefficients) => ({ coefficients: trim(coefficients), denominator }));
}

function trim(p: readonly number[]): number[] {
  const out = [...p];
  while (out.length > 1 && out[out.length - 1] === 0) out.pop();
  return out;
}

/** The piece's value at t. */
export const pieceAt = ({ coefficients, denominator }: Piece, t: number): number =>
  coefficients.reduceRight((sum, c) => sum * t + c, 0) / denominator;

/** (1 − t)^r expanded, lowest power first. */
function oneMinusPower(r: number): number[] {
  let p = [1];
  for (let q = 0; q < r; q++) p = timesLinear(p, 1, -1);
  return p;
}

const same = (p: readonly number[], q: readonly number[]) =>
  p.length === q.length && p.every((c, k) => c === q[k]);

/** A power of t in TeX: 1, t, t^{2}. */
const power = (k: number) => (k === 0 ? '' : k === 1 ? 't' : `t^{${k}}`);

/**
 * The polynomial as the notes write it, highest power first: (1−t)^3,
 * 3t^{3} - 6t^{2} + 4, t^{3} (a factor (1 − t)^r or t^r kept whole).
 */
export function polynomialTex(coefficients: readonly number[]): string {
  const r = coefficients.length - 1;
  if (r >= 1 && same(coefficients, oneMinusPower(r))) return r === 1 ? '1 - t' : `(1 - t)^{${r}}`;
  const terms: string[] = [];
  for (let k = r; k >= 0; k--) {
    const c = coefficients[k];
    if (c === 0) continue;
    const size = Math.abs(c);
    const body = k > 0 && size === 1 ? power(k) : `${size}${power(k)}`;
    terms.push(terms.length === 0 ? `${c < 0 ? '-' : ''}${body}` : `${c < 0 ? '-' : '+'} ${body}`);
  }
  return terms.length === 0 ? '0' : terms.join(' ');
}

/** The piece in TeX: \tfrac16(3t^{3} - 6t^{2} + 4), \tfrac12 t^{2}, 1 - t, 1. */
export function pieceTex(piece: Piece): string {
  const body = polynomialTex(piece.coefficients);
  if (piece.denominator === 1) return body;
  const fraction = `\\tfrac{1}{${piece.denominator}}`;
  const single = /^[(]?[^+-]*$/.test(body) || /^\(1 - t\)\^/.test(body);
  return single ? `${fraction}${body}` : `${fraction}(${body})`;
}

/** Equal spacing h > 0 of the knots u_from … u_to (all of them), else null. */
export function equalSpacing(knots: readonly number[], from: number, to: number): number | null {
  if (from < 0 || to >= knots.length || to <= from) return null;
  const h = knots[from + 1] - knots[from];
  if (!(h > 0)) return null;
  for (let j = from + 1; j < to; j++) {
    if (Math.abs(knots[j + 1] - knots[j] - h) > 1e-9 * Math.max(1, Math.abs(h))) return null;
  }
  return h;
}

/** A number in a piece's line: three decimals. */
export const pieceNumber = (v: number) => texNumber(v, 3);
