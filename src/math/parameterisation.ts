import { checkPoint, checkPoints } from './checkPoints';
import { checkParameter } from './validate';
import { distance, type Point } from './vec';

// Choosing parameter values from the geometry (lecture notes, parametric
// quadratic; Lee 1989 for centripetal): the gap between consecutive
// parameters is |P(i+1) − Pi|^alpha, with alpha = 0 uniform, 1/2 centripetal,
// 1 chord length.

/**
 * `mu` for the parametric quadratic through p0, p1, p2 by chord length:
 * `|P1 − P0| / (|P1 − P0| + |P2 − P1|)`. 1/2 when all three points coincide.
 */
export function chordLengthMu(p0: Point, p1: Point, p2: Point): number {
  return quadraticMu('chordLengthMu', p0, p1, p2, 1);
}

/**
 * `mu` for the parametric quadratic by the centripetal rule:
 * `√|P1 − P0| / (√|P1 − P0| + √|P2 − P1|)`. 1/2 when all three points coincide.
 */
export function centripetalMu(p0: Point, p1: Point, p2: Point): number {
  return quadraticMu('centripetalMu', p0, p1, p2, 0.5);
}

/**
 * Parameter values `t0 = 0 < … < tm = 1` for points, with gaps proportional to
 * `|P(i+1) − Pi|^alpha` (alpha ∈ [0, 1]: 0 uniform, 0.5 centripetal, 1 chord
 * length). Repeated points give repeated values; if every point coincides the
 * values fall back to uniform.
 */
export function parameterValues(points: readonly Point[], alpha: number): number[] {
  checkPoints('parameterValues', 'points', points, 1);
  checkParameter('parameterValues', 'alpha', alpha, 0, 1);
  const m = points.length - 1;
  const values = new Array<number>(m + 1);
  values[0] = 0;
  for (let i = 1; i <= m; i++) {
    values[i] = values[i - 1] + distance(points[i - 1], points[i]) ** alpha;
  }
  const total = values[m];
  for (let i = 1; i <= m; i++) values[i] = total > 0 ? values[i] / total : i / m;
  return values;
}

function quadraticMu(caller: string, p0: Point, p1: Point, p2: Point, alpha: number): number {
  const dimension = checkPoint(caller, 'p0', p0);
  checkPoint(caller, 'p1', p1, dimension);
  checkPoint(caller, 'p2', p2, dimension);
  const first = distance(p0, p1) ** alpha;
  const second = distance(p1, p2) ** alpha;
  return first + second > 0 ? first / (first + second) : 0.5;
}
