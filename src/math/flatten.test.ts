import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { polygon } from './arbitraries.test-helpers';
import { sampleBezier } from './bezier';
import { flattenBezier } from './flatten';
import type { Point } from './vec';

function distanceToSegment(p: readonly number[], a: Point, b: Point): number {
  let along = 0;
  let length = 0;
  for (let d = 0; d < p.length; d++) {
    along += (p[d] - a[d]) * (b[d] - a[d]);
    length += (b[d] - a[d]) ** 2;
  }
  const t = length > 0 ? Math.min(1, Math.max(0, along / length)) : 0;
  let squared = 0;
  for (let d = 0; d < p.length; d++) squared += (p[d] - (a[d] + t * (b[d] - a[d]))) ** 2;
  return Math.sqrt(squared);
}

function uniformCount(points: readonly Point[], tolerance: number): number {
  const n = points.length - 1;
  let maximum = 0;
  for (let i = 0; i + 2 <= n; i++) {
    maximum = Math.max(
      maximum,
      Math.hypot(...points[i].map((value, d) => points[i + 2][d] - 2 * points[i + 1][d] + value)),
    );
  }
  return Math.ceil(Math.sqrt((n * (n - 1) * maximum) / (8 * tolerance)));
}

const tolerance = fc.double({ min: 0.05, max: 5, noNaN: true });

describe('flattenBezier', () => {
  it('starts at P0, ends at Pn, stays within tolerance both ways and respects 4N + 16', () => {
    fc.assert(
      fc.property(polygon(1, 7), tolerance, (points, tol) => {
        const polyline = flattenBezier(points, tol);
        const n = points.length - 1;
        expect(polyline[0]).toEqual(points[0]);
        expect(polyline[polyline.length - 1]).toEqual(points[n]);
        expect(polyline.length).toBeLessThanOrEqual(4 * uniformCount(points, tol) + 16);
        const dimension = points[0].length;
        const count = 4096;
        const samples = sampleBezier(points, count);
        const sample = (j: number) =>
          Array.from(samples.subarray(j * dimension, (j + 1) * dimension));
        // Every curve point near the polyline.
        for (let j = 0; j <= count; j += 4) {
          const p = sample(j);
          let nearest = distanceToSegment(p, polyline[0], polyline[0]);
          for (let i = 1; i < polyline.length; i++) {
            nearest = Math.min(nearest, distanceToSegment(p, polyline[i - 1], polyline[i]));
          }
          expect(nearest).toBeLessThanOrEqual(tol * (1 + 1e-9));
        }
        // Every vertex on the curve: bisection vertices sit at dyadic t, so at samples.
        for (const vertex of polyline) {
          let nearest = Infinity;
          for (let j = 0; j <= count; j++) {
            let squared = 0;
            for (let d = 0; d < dimension; d++)
              squared += (samples[j * dimension + d] - vertex[d]) ** 2;
            nearest = Math.min(nearest, squared);
          }
          expect(Math.sqrt(nearest)).toBeLessThanOrEqual(
            1e-9 * Math.max(1, ...vertex.map(Math.abs)),
          );
        }
      }),
      { numRuns: 40 },
    );
  });

  it('needs only the two end points for a straight segment and degree 0 or 1', () => {
    expect(
      flattenBezier(
        [
          [0, 0],
          [1, 1],
          [2, 2],
        ],
        0.1,
      ),
    ).toEqual([
      [0, 0],
      [2, 2],
    ]);
    expect(flattenBezier([[5, 5]], 0.1)).toEqual([[5, 5]]);
    expect(
      flattenBezier(
        [
          [0, 0, 0],
          [1, 2, 3],
        ],
        0.1,
      ),
    ).toEqual([
      [0, 0, 0],
      [1, 2, 3],
    ]);
  });

  it('spends its points where the curve bends', () => {
    // Almost straight on the left half, a tight turn at the right end.
    const points: Point[] = [
      [0, 0],
      [100, 0],
      [200, 0],
      [200, 50],
    ];
    const polyline = flattenBezier(points, 0.1);
    const left = polyline.filter(([x]) => x < 60).length;
    const right = polyline.filter(([x]) => x > 140).length;
    expect(right).toBeGreaterThan(left);
  });

  it('rejects a tolerance that is not positive', () => {
    for (const bad of [0, -1, NaN, Infinity]) {
      expect(() =>
        flattenBezier(
          [
            [0, 0],
            [1, 1],
          ],
          bad,
        ),
      ).toThrow(/tolerance = .*positive finite distance/);
    }
  });

  it('terminates for a tolerance below the precision of large coordinates', () => {
    // Near 1e12 doubles are 1.2e-4 apart, so rounding noise in the second
    // differences exceeds a tolerance of 1e-5: the depth cap must stop it.
    const points: Point[] = [
      [1e12, 1e12],
      [1e12 + 1, 1e12 + 3],
      [1e12 + 3, 1e12 - 2],
      [1e12 + 4, 1e12],
    ];
    const polyline = flattenBezier(points, 1e-5);
    expect(polyline.length).toBeLessThanOrEqual(4 * uniformCount(points, 1e-5) + 16);
    expect(polyline[polyline.length - 1]).toEqual(points[3]);
  });
});
