import { splitBezier } from './bezier';
import { checkPoints } from './checkPoints';
import { checkInteger, checkParameter } from './validate';
import type { Point } from './vec';

/**
 * Repeated subdivision (Lane and Riesenfeld, 1980): every piece split at t by
 * de Casteljau, `levels` times. Returns every level: `result[j]` holds the
 * 2ʲ control polygons after j splits, left to right, `result[0]` the curve's
 * own. Their polygons converge to the curve, which is how curves are drawn and
 * intersected in practice.
 */
export function subdivisionLevels(
  points: readonly Point[],
  t: number,
  levels: number,
): Point[][][] {
  checkPoints('subdivisionLevels', 'points', points, 1);
  checkParameter('subdivisionLevels', 't', t, 0, 1);
  checkInteger('subdivisionLevels', 'levels', levels, 0);
  const result: Point[][][] = [[points.slice()]];
  for (let j = 0; j < levels; j++) result.push(result[j].flatMap((piece) => splitBezier(piece, t)));
  return result;
}
