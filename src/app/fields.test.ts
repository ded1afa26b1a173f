import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { knots, pointGrid, points, weights } from './fields';

describe('field kinds', () => {
  it('3D points read and write x,y,z and refuse two coordinates', () => {
    const field = points({ default: [[0, 0, 0]], min: 1, max: 4, dimension: 3 });
    expect(field.decode('1,2,3;-4,0.5,6')).toEqual({
      ok: true,
      value: [
        [1, 2, 3],
        [-4, 0.5, 6],
      ],
    });
    expect(field.encode([[1, 2, 3]])).toBe('1,2,3');
    const two = field.decode('1,2');
    expect(two.ok).toBe(false);
    if (!two.ok) expect(two.why).toMatch(/not a point x,y,z/);
  });

  it('knots must never decrease, and say which one does', () => {
    const field = knots({ default: [0, 0, 1, 1], min: 2, max: 20, low: -100, high: 100 });
    expect(field.decode('0,0,0,1,2,2,2')).toEqual({ ok: true, value: [0, 0, 0, 1, 2, 2, 2] });
    const bad = field.decode('0,1,0.5,2');
    expect(bad.ok).toBe(false);
    if (!bad.ok) expect(bad.why).toBe('knot 2 (0.5) is below knot 1 (1): knots never decrease');
  });

  it('weights are positive', () => {
    const field = weights({ default: [1, 1], min: 1, max: 5, high: 100 });
    expect(field.decode('1,0.7071067812,1').ok).toBe(true);
    expect(field.decode('1,0,1').ok).toBe(false);
  });

  it('a 4 × 4 grid of 3D points round-trips and must be whole', () => {
    const coordinate = fc.double({ min: -1e3, max: 1e3, noNaN: true });
    const grid = pointGrid({ default: [], rows: 4, columns: 4, dimension: 3 });
    fc.assert(
      fc.property(
        fc.array(
          fc.array(fc.tuple(coordinate, coordinate, coordinate), { minLength: 4, maxLength: 4 }),
          {
            minLength: 4,
            maxLength: 4,
          },
        ),
        (net) => {
          const back = grid.decode(grid.encode(net));
          expect(back.ok).toBe(true);
          if (back.ok)
            back.value.forEach((row, r) =>
              row.forEach((p, c) => p.forEach((v, k) => expect(v).toBeCloseTo(net[r][c][k], 6))),
            );
        },
      ),
    );
    const short = grid.decode('0,0,0;1,1,1');
    expect(short.ok).toBe(false);
    if (!short.ok) expect(short.why).toBe('2 points given, a 4 × 4 grid needs 16');
  });
});
