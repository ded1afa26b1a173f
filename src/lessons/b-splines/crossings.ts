import type { Point } from '../../math';

/** How often a line crosses the control polygon and the curve, and where. */
export interface Crossings {
  polygon: number;
  curve: number;
  polygonPoints: Point[];
  curvePoints: Point[];
}

/**
 * Sign changes of the signed distance to the line through `line[0]`, `line[1]`
 * along the polygon's vertices and along the curve's samples (variation
 * diminishing: the curve never crosses more often than the polygon).
 */
export function crossings(
  line: readonly Point[],
  polygon: readonly Point[],
  segments: readonly { samples: Float64Array }[],
): Crossings {
  const [a, b] = line;
  const side = (x: number, y: number) => (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
  const polygonPath = polygon.flatMap((point) => [point[0], point[1]]);
  const curvePath: number[] = [];
  for (const segment of segments) curvePath.push(...segment.samples);
  const onPolygon = signChanges(polygonPath, side);
  const onCurve = signChanges(curvePath, side);
  return {
    polygon: onPolygon.length,
    curve: onCurve.length,
    polygonPoints: onPolygon,
    curvePoints: onCurve,
  };
}

/** Where the sign of `side` changes along a path of interleaved x, y (zeros carry the sign before). */
function signChanges(path: readonly number[], side: (x: number, y: number) => number): Point[] {
  const points: Point[] = [];
  let previous = 0;
  let px = 0;
  let py = 0;
  let pv = 0;
  for (let k = 0; k < path.length; k += 2) {
    const x = path[k];
    const y = path[k + 1];
    const v = side(x, y);
    const sign = Math.sign(v);
    if (sign !== 0 && previous !== 0 && sign !== previous) {
      const f = pv / (pv - v);
      points.push([px + f * (x - px), py + f * (y - py)]);
    }
    if (sign !== 0) {
      previous = sign;
      px = x;
      py = y;
      pv = v;
    }
  }
  return points;
}
