import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { polygon2D } from './arbitraries.test-helpers';
import { cubicInflections } from './cubicInflections';
import { bezierCurvature } from './curvature';

describe('cubicInflections', () => {
  it('finds the middle of a symmetric S-curve', () => {
    const t = cubicInflections([
      [0, 0],
      [1, 1],
      [2, -1],
      [3, 0],
    ]);
    expect(t).toHaveLength(1);
    expect(t[0]).toBeCloseTo(0.5, 12);
  });

  it('finds none on a C-shaped arch or a loop', () => {
    expect(
      cubicInflections([
        [0, 0],
        [1, 2],
        [3, 2],
        [4, 0],
      ]),
    ).toEqual([]);
    expect(
      cubicInflections([
        [0, 0],
        [5, 3],
        [-1, 3],
        [4, 0],
      ]),
    ).toEqual([]);
  });

  it('finds two on a curve that waves twice', () => {
    // P0 … P3 = (0,0), (0,1), (1,1), (−3,−2): P′×P″ ∝ 8t² − 6t + 1, roots 1/4 and 1/2.
    const t = cubicInflections([
      [0, 0],
      [0, 1],
      [1, 1],
      [-3, -2],
    ]);
    expect(t).toHaveLength(2);
    expect(t[0]).toBeCloseTo(0.25, 12);
    expect(t[1]).toBeCloseTo(0.5, 12);
  });

  it('finds none on straight and degenerate cubics', () => {
    const line = [
      [0, 0],
      [1, 1],
      [2, 2],
      [3, 3],
    ];
    expect(cubicInflections(line)).toEqual([]);
    expect(
      cubicInflections([
        [1, 1],
        [1, 1],
        [1, 1],
        [1, 1],
      ]),
    ).toEqual([]);
  });

  it('rejects anything but a 2D cubic', () => {
    expect(() =>
      cubicInflections([
        [0, 0],
        [1, 1],
        [2, 0],
      ]),
    ).toThrow(RangeError);
    expect(() =>
      cubicInflections([
        [0, 0, 0],
        [1, 1, 0],
        [2, 0, 0],
        [3, 1, 0],
      ]),
    ).toThrow(RangeError);
  });

  it('the curvature changes sign across every inflection found', () => {
    fc.assert(
      fc.property(polygon2D(4, 4), (points) => {
        // A polygon straight but for rounding (fast-check found one 1800 wide and
        // 2e-8 high) has inflections of noise, and curvatures of noise around them.
        const extent = Math.max(...points.flat().map(Math.abs), 1e-300);
        const [a, b] = [points[0], points[3]];
        const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
        const height = (p: readonly number[]) =>
          length === 0
            ? Math.hypot(p[0] - a[0], p[1] - a[1])
            : Math.abs((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / length;
        if (Math.max(...points.map(height)) < 1e-9 * extent) return;
        const roots = cubicInflections(points);
        for (const t of roots) {
          // Probe closer than any other inflection, or the two sign changes cancel
          // (fast-check found a pair 1.5e-8 apart); a near-double root is a
          // tangency in all but rounding, with no sign change to see.
          const gap = Math.min(...roots.filter((r) => r !== t).map((r) => Math.abs(r - t)));
          const h = Math.min(1e-4, gap / 3);
          if (h < 1e-7 || t - h < 0 || t + h > 1) continue;
          let before: number;
          let after: number;
          try {
            before = bezierCurvature(points, t - h);
            after = bezierCurvature(points, t + h);
          } catch {
            continue; // zero speed nearby: a cusp, curvature undefined
          }
          // Near a root both may be tiny; a genuine sign change is what counts.
          if (Math.abs(before) > 1e-9 && Math.abs(after) > 1e-9) {
            expect(Math.sign(before)).not.toBe(Math.sign(after));
          }
        }
      }),
    );
  });
});
