import { checkPoints } from './checkPoints';
import { checkNumber, checkNumbers, checkSameLength } from './validate';
import type { Point } from './vec';

// Lagrange interpolation (lecture notes): the polynomial of degree n through
// (t_k, P_k), P(t) = Σ_k L_k(t) P_k with L_k(t) = Π_{j≠k} (t − t_j) / (t_k − t_j).

/**
 * The Lagrange basis values `[L0(t) … Ln(t)]` for the nodes `ts`, at any finite
 * t (for plotting the basis). At a node `t = ts[k]` they are exactly 1 and 0s.
 */
export function lagrangeBasis(ts: readonly number[], t: number): number[] {
  checkNodes('lagrangeBasis', ts);
  checkNumber('lagrangeBasis', 't', t);
  const values = new Array<number>(ts.length);
  fillLagrange(ts, t, values);
  return values;
}

/**
 * The Lagrange interpolating polynomial through `(ts[k], points[k])`,
 * evaluated at any finite t (outside the nodes it extrapolates).
 */
export function lagrangePoint(ts: readonly number[], points: readonly Point[], t: number): Point {
  checkNodes('lagrangePoint', ts);
  const dimension = checkPoints('lagrangePoint', 'points', points, 1);
  checkSameLength('lagrangePoint', 'ts', ts, 'points', points);
  checkNumber('lagrangePoint', 't', t);
  const result = new Array<number>(dimension).fill(0);
  for (let k = 0; k < ts.length; k++) {
    const weight = lagrangeValue(ts, k, t);
    if (weight === 0) continue;
    const point = points[k];
    for (let d = 0; d < dimension; d++) result[d] += weight * point[d];
  }
  return result;
}

function fillLagrange(ts: readonly number[], t: number, out: number[]): void {
  for (let k = 0; k < ts.length; k++) out[k] = lagrangeValue(ts, k, t);
}

function lagrangeValue(ts: readonly number[], k: number, t: number): number {
  let value = 1;
  const node = ts[k];
  for (let j = 0; j < ts.length; j++) {
    if (j !== k) value *= (t - ts[j]) / (node - ts[j]);
  }
  return value;
}

function checkNodes(caller: string, ts: readonly number[]): void {
  checkNumbers(caller, 'ts', ts, 1);
  for (let k = 1; k < ts.length; k++) {
    for (let j = 0; j < k; j++) {
      if (ts[j] === ts[k]) {
        throw new RangeError(
          `${caller}: ts[${j}] and ts[${k}] are both ${ts[k]}; the parameter values must all differ.`,
        );
      }
    }
  }
}
