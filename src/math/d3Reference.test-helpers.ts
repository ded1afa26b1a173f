import type { CurveFactory } from 'd3-shape';
import type { Point } from './vec';

/**
 * Runs a d3-shape curve (curveNatural, curveBasis) through `points` and
 * records its bezierCurveTo calls, [x1, y1, x2, y2, x, y] each: d3 draws its
 * splines as cubic Bézier segments, so these are its control points.
 */
export function recordD3Bezier(factory: CurveFactory, points: readonly Point[]): number[][] {
  const calls: number[][] = [];
  const context = {
    moveTo: () => undefined,
    lineTo: () => undefined,
    closePath: () => undefined,
    bezierCurveTo: (...args: number[]) => void calls.push(args),
  };
  const curve = factory(context as unknown as CanvasRenderingContext2D);
  curve.lineStart();
  for (const [x, y] of points) curve.point(x, y);
  curve.lineEnd();
  return calls;
}
