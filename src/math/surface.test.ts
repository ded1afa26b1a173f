import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point, unitParameter } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { bezierSurfaceDerivatives, bezierSurfaceNormal, bezierSurfacePoint } from './surface';
import type { Point } from './vec';

const grid = (rows: number, columns: number) =>
  fc.array(fc.array(point(3), { minLength: columns, maxLength: columns }), {
    minLength: rows,
    maxLength: rows,
  });

const anyGrid = fc
  .tuple(fc.integer({ min: 1, max: 5 }), fc.integer({ min: 1, max: 5 }))
  .chain(([r, c]) => grid(r, c));

/** A flat bicubic patch z = 0 over [0, 3]²: x = 3u, y = 3v. */
const flat: Point[][] = [0, 1, 2, 3].map((m) => [0, 1, 2, 3].map((n) => [m, n, 0]));

describe('bezierSurfacePoint', () => {
  it('is a Bézier curve along each boundary and interpolates the corners', () => {
    fc.assert(
      fc.property(anyGrid, unitParameter, (net, t) => {
        const last = net.length - 1;
        const lastColumn = net[0].length - 1;
        expectClose(bezierSurfacePoint(net, 0, t), bezierPoint(net[0], t), 1e-9);
        expectClose(bezierSurfacePoint(net, 1, t), bezierPoint(net[last], t), 1e-9);
        expectClose(
          bezierSurfacePoint(net, t, 0),
          bezierPoint(
            net.map((row) => row[0]),
            t,
          ),
          1e-9,
        );
        expect(bezierSurfacePoint(net, 1, 1)).toEqual(net[last][lastColumn]);
      }),
    );
  });

  it('is the tensor product: evaluate columns in v, then the results in u', () => {
    fc.assert(
      fc.property(anyGrid, unitParameter, unitParameter, (net, u, v) => {
        const curve = net.map((row) => bezierPoint(row, v));
        expectClose(bezierSurfacePoint(net, u, v), bezierPoint(curve, u), 1e-9);
      }),
    );
  });

  it('reproduces a flat patch', () => {
    expectClose(bezierSurfacePoint(flat, 0.5, 0.25), [1.5, 0.75, 0]);
  });

  it('rejects ragged grids and out-of-range parameters', () => {
    expect(() =>
      bezierSurfacePoint(
        [
          [
            [0, 0, 0],
            [1, 0, 0],
          ],
          [[0, 1, 0]],
        ],
        0.5,
        0.5,
      ),
    ).toThrow(/must be rectangular/);
    expect(() => bezierSurfacePoint(flat, 1.5, 0.5)).toThrow(/u = 1.5 is outside/);
    expect(() => bezierSurfacePoint([], 0, 0)).toThrow(/at least one row/);
  });
});

describe('partial derivatives and normal', () => {
  it('match central differences', () => {
    fc.assert(
      fc.property(
        anyGrid,
        fc.double({ min: 0.01, max: 0.99, noNaN: true }),
        fc.double({ min: 0.01, max: 0.99, noNaN: true }),
        (net, u, v) => {
          const h = 1e-6;
          const { du, dv } = bezierSurfaceDerivatives(net, u, v);
          const [uAhead, uBehind] = [
            bezierSurfacePoint(net, u + h, v),
            bezierSurfacePoint(net, u - h, v),
          ];
          const [vAhead, vBehind] = [
            bezierSurfacePoint(net, u, v + h),
            bezierSurfacePoint(net, u, v - h),
          ];
          expectClose(
            du,
            uAhead.map((value, d) => (value - uBehind[d]) / (2 * h)),
            1e-4,
          );
          expectClose(
            dv,
            vAhead.map((value, d) => (value - vBehind[d]) / (2 * h)),
            1e-4,
          );
        },
      ),
    );
  });

  it('give the normal of a flat patch as +z', () => {
    const { du, dv } = bezierSurfaceDerivatives(flat, 0.3, 0.6);
    expectClose(du, [3, 0, 0]);
    expectClose(dv, [0, 3, 0]);
    expectClose(bezierSurfaceNormal(flat, 0.3, 0.6), [0, 0, 1]);
  });

  it('reject a normal where the patch degenerates, and 2D grids', () => {
    const collapsed: Point[][] = [
      [
        [0, 0, 0],
        [0, 0, 0],
      ],
      [
        [1, 0, 0],
        [1, 1, 0],
      ],
    ];
    expect(() => bezierSurfaceNormal(collapsed, 0, 0.5)).toThrow(/parallel or zero/);
    expect(() =>
      bezierSurfaceNormal(
        [
          [
            [0, 0],
            [1, 0],
          ],
        ],
        0.5,
        0.5,
      ),
    ).toThrow(/needs 3D points/);
  });
});
