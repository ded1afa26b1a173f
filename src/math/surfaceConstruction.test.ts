import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, unitParameter } from './arbitraries.test-helpers';
import { bezierSurfacePoint } from './surface';
import {
  surfaceColumnPoints,
  surfaceDeCasteljau,
  surfaceRowPoints,
  surfaceWeights,
} from './surfaceConstruction';
import type { Point } from './vec';

/** x(m,n) = (m, n, m·n): since Σ m·fm(u) = 3u, the patch is (3u, 3v, 9uv). */
const saddle: Point[][] = [0, 1, 2, 3].map((m) => [0, 1, 2, 3].map((n) => [m, n, m * n]));

/** A bump: height 1 at the four inner control points, 0 on the border. */
const bump: Point[][] = [0, 1, 2, 3].map((m) =>
  [0, 1, 2, 3].map((n) => [m, n, m % 3 !== 0 && n % 3 !== 0 ? 1 : 0]),
);

const bicubic = fc.array(fc.array(point(3), { minLength: 4, maxLength: 4 }), {
  minLength: 4,
  maxLength: 4,
});

describe('surfaceRowPoints and surfaceColumnPoints', () => {
  it('give the control points of the iso-curves of the saddle, by hand', () => {
    // Row m at v = 1/4: Σn fn(v)·(m, n, m·n) = (m, 3v, 3v·m) = (m, 0.75, 0.75·m).
    const rows = surfaceRowPoints(saddle, 0.25);
    [0, 1, 2, 3].forEach((m) => expectClose(rows[m], [m, 0.75, 0.75 * m], 1e-15));
    // Column n at u = 1/2: (3u, n, 3u·n) = (1.5, n, 1.5·n).
    const columns = surfaceColumnPoints(saddle, 0.5);
    [0, 1, 2, 3].forEach((n) => expectClose(columns[n], [1.5, n, 1.5 * n], 1e-15));
  });

  it('give the bump its inner height 3/8 + 3/8 = 3/4 at v = 1/2', () => {
    expect(surfaceRowPoints(bump, 0.5)).toEqual([
      [0, 1.5, 0],
      [1, 1.5, 0.75],
      [2, 1.5, 0.75],
      [3, 1.5, 0],
    ]);
  });

  it('are the first and last rows and columns at the edges of the patch', () => {
    expect(surfaceRowPoints(saddle, 0)).toEqual(saddle.map((row) => row[0]));
    expect(surfaceRowPoints(saddle, 1)).toEqual(saddle.map((row) => row[3]));
    expect(surfaceColumnPoints(saddle, 0)).toEqual(saddle[0]);
    expect(surfaceColumnPoints(saddle, 1)).toEqual(saddle[3]);
  });

  it('reject a ragged net and parameters outside [0, 1]', () => {
    expect(() => surfaceRowPoints([[[0, 0, 0]], []], 0.5)).toThrow(RangeError);
    expect(() => surfaceRowPoints(saddle, 1.5)).toThrow(RangeError);
    expect(() => surfaceColumnPoints(saddle, Number.NaN)).toThrow(RangeError);
  });
});

describe('surfaceDeCasteljau', () => {
  it('finds the saddle point (3u, 3v, 9uv) both ways', () => {
    for (const order of ['u-then-v', 'v-then-u'] as const) {
      const c = surfaceDeCasteljau(saddle, 0.5, 0.25, order);
      expectClose(c.point, [1.5, 0.75, 1.125], 1e-15);
      expect(c.first).toHaveLength(4);
      expect(c.second.map((level) => level.length)).toEqual([4, 3, 2, 1]);
    }
    // u first: the columns give c_n(1/2) = (1.5, n, 1.5·n).
    const uFirst = surfaceDeCasteljau(saddle, 0.5, 0.25, 'u-then-v');
    [0, 1, 2, 3].forEach((n) => expectClose(uFirst.intermediate[n], [1.5, n, 1.5 * n], 1e-15));
  });

  it('gives the bump 9/16 at its centre', () => {
    // Σ over the inner points of fm(½)·fn(½) = (3/8 + 3/8)² = 9/16.
    expect(surfaceDeCasteljau(bump, 0.5, 0.5, 'v-then-u').point).toEqual([1.5, 1.5, 0.5625]);
  });

  it('agrees in both orders with the rows, the columns and the Bernstein sum', () => {
    fc.assert(
      fc.property(bicubic, unitParameter, unitParameter, (net, u, v) => {
        const a = surfaceDeCasteljau(net, u, v, 'u-then-v');
        const b = surfaceDeCasteljau(net, u, v, 'v-then-u');
        expectClose(a.point, b.point, 1e-9);
        expectClose(a.point, bezierSurfacePoint(net, u, v), 1e-9);
        surfaceColumnPoints(net, u).forEach((c, n) => expectClose(a.intermediate[n], c, 1e-9));
        surfaceRowPoints(net, v).forEach((r, m) => expectClose(b.intermediate[m], r, 1e-9));
      }),
    );
  });
});

describe('surfaceWeights', () => {
  it('are products of the cubic Bernstein values, by hand', () => {
    // f(½) = (1, 3, 3, 1)/8 and f(¼) = (27, 27, 9, 1)/64.
    const w = surfaceWeights(4, 4, 0.5, 0.25);
    expect(w[0][0]).toBe(27 / 512);
    expect(w[1][2]).toBe((3 / 8) * (9 / 64));
    expect(w[3][3]).toBe(1 / 512);
    expect(surfaceWeights(4, 4, 0, 1)).toEqual([
      [0, 0, 0, 1],
      [0, 0, 0, 0],
      [0, 0, 0, 0],
      [0, 0, 0, 0],
    ]);
  });

  it('are never negative and sum to 1 (the convex-hull property)', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 6 }),
        fc.integer({ min: 1, max: 6 }),
        unitParameter,
        unitParameter,
        (rows, columns, u, v) => {
          const w = surfaceWeights(rows, columns, u, v).flat();
          expect(w).toHaveLength(rows * columns);
          expect(Math.min(...w)).toBeGreaterThanOrEqual(0);
          expect(Math.abs(w.reduce((sum, x) => sum + x, 0) - 1)).toBeLessThan(1e-12);
        },
      ),
    );
  });

  it('weigh the net into the patch point', () => {
    const w = surfaceWeights(4, 4, 0.3, 0.7);
    const z = w.reduce(
      (sum, row, m) => sum + row.reduce((s, x, n) => s + x * saddle[m][n][2], 0),
      0,
    );
    expect(z).toBeCloseTo(9 * 0.3 * 0.7, 14);
    expect(() => surfaceWeights(0, 4, 0.5, 0.5)).toThrow(RangeError);
  });
});
