import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { cubicSplineC2 } from './bezierSpline';
import { cubicSplineC2System, solveCubicSplineC2System, solveDense } from './bezierSplineSystem';
import { naturalCubicDerivatives } from './naturalCubic';

describe('cubicSplineC2System', () => {
  it('has the practical’s 8 equations and 2 end conditions for four points A, D, G, J', () => {
    const rows = cubicSplineC2System([
      [0, 0],
      [1, 1],
      [2, 0],
      [3, 1],
    ]);
    expect(rows).toHaveLength(10);
    expect(rows.map((r) => r.kind)).toEqual([
      'point',
      'point',
      'point',
      'point',
      'C1',
      'C1',
      'C2',
      'C2',
      'natural',
      'natural',
    ]);
    // C¹ at D: C − 2D + E = 0; C² at D: B − 2C + 2E − F = 0; natural at A: A − 2B + C = 0.
    expect(rows[4].coefficients).toEqual([0, 0, 1, -2, 1, 0, 0, 0, 0, 0]);
    expect(rows[6].coefficients).toEqual([0, 1, -2, 0, 2, -1, 0, 0, 0, 0]);
    expect(rows[8].coefficients).toEqual([1, -2, 1, 0, 0, 0, 0, 0, 0, 0]);
    expect(rows[9].coefficients).toEqual([0, 0, 0, 0, 0, 0, 0, 1, -2, 1]);
    expect(rows[2].right).toEqual([2, 0]);
  });

  it('solves y = 0, 1, 0 by hand: D = 1.5, 0, −1.5 so the inner points are 0.5, 1 | 1, 0.5', () => {
    // 2D0 + D1 = 3, D0 + 4D1 + D2 = 0, D1 + 2D2 = −3 → D1 = 0, D0 = 1.5, D2 = −1.5.
    const { controls, residual } = solveCubicSplineC2System([[0], [1], [0]]);
    expect(controls.map((c) => c[0])).toEqual(
      [0, 0.5, 1, 1, 1, 0.5, 0].map((v) => expect.closeTo(v, 14)),
    );
    expect(residual).toBeLessThan(1e-14);
  });

  it('gives a straight line’s thirds for evenly spaced points on a line', () => {
    const { controls } = solveCubicSplineC2System([
      [0, 0],
      [3, 3],
      [6, 6],
    ]);
    controls.forEach((c, j) => {
      expect(c[0]).toBeCloseTo(j, 12);
      expect(c[1]).toBeCloseTo(j, 12);
    });
  });

  it('equals the natural cubic spline (cubicSplineC2 and naturalCubicDerivatives) for any points', () => {
    const coordinate = fc.double({ min: -100, max: 100, noNaN: true });
    fc.assert(
      fc.property(
        fc.array(fc.tuple(coordinate, coordinate), { minLength: 2, maxLength: 9 }),
        (raw) => {
          const points = raw.map(([x, y]) => [x, y]);
          const { controls, residual } = solveCubicSplineC2System(points);
          const segments = cubicSplineC2(points);
          const dx = naturalCubicDerivatives(points.map((p) => p[0]));
          segments.forEach((segment, i) => {
            segment.forEach((q, k) => {
              expect(controls[3 * i + k][0]).toBeCloseTo(q[0], 7);
              expect(controls[3 * i + k][1]).toBeCloseTo(q[1], 7);
            });
            expect(controls[3 * i + 1][0]).toBeCloseTo(points[i][0] + dx[i] / 3, 7);
          });
          expect(residual).toBeLessThan(1e-9);
        },
      ),
    );
  });
});

describe('solveDense', () => {
  it('pivots past a zero on the diagonal', () => {
    expect(
      solveDense(
        [
          [0, 1],
          [1, 0],
        ],
        [[2], [3]],
      ),
    ).toEqual([[3], [2]]);
  });
  it('refuses a singular matrix', () => {
    expect(() =>
      solveDense(
        [
          [1, 2],
          [2, 4],
        ],
        [[1], [2]],
      ),
    ).toThrow(RangeError);
  });
});
