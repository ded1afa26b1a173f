import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { pointsShape } from './pointsShape';

describe('pointsShape', () => {
  it('names the degenerate cases the lessons explain, by hand', () => {
    expect(
      pointsShape([
        [2, 3],
        [2, 3],
        [2, 3],
        [2, 3],
      ]),
    ).toEqual({ kind: 'one spot' });
    expect(
      pointsShape([
        [0, 0],
        [1, 2],
        [3, 6],
        [-1, -2],
      ]),
    ).toEqual({ kind: 'one line' });
    expect(
      pointsShape([
        [0, 0],
        [1, 2],
        [1, 2],
        [4, 0],
      ]),
    ).toEqual({
      kind: 'neighbours on one spot',
      index: 1,
    });
    expect(
      pointsShape([
        [0, 0],
        [1, 2],
        [3, 2],
        [4, 0],
      ]),
    ).toEqual({ kind: 'general' });
    // One point, or two apart: a spot, a line.
    expect(pointsShape([[5, 5]])).toEqual({ kind: 'one spot' });
    expect(
      pointsShape([
        [0, 0],
        [1, 1],
      ]),
    ).toEqual({ kind: 'one line' });
  });

  it('judges a figure the same at any scale and position', () => {
    const point = fc.tuple(fc.integer({ min: -50, max: 50 }), fc.integer({ min: -50, max: 50 }));
    fc.assert(
      fc.property(
        fc.array(point, { minLength: 1, maxLength: 8 }),
        fc.constantFrom(1e-6, 1, 1e6),
        fc.tuple(
          fc.double({ min: -1e3, max: 1e3, noNaN: true }),
          fc.double({ min: -1e3, max: 1e3, noNaN: true }),
        ),
        (points, k, [dx, dy]) => {
          const moved = points.map(
            ([x, y]) => [x * k + dx * k, y * k + dy * k] as [number, number],
          );
          expect(pointsShape(moved).kind).toBe(pointsShape(points).kind);
        },
      ),
    );
  });
});
