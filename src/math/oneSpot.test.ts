import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { onOneSpot } from './oneSpot';

describe('onOneSpot', () => {
  it('says yes for copies of one point in 2D and 3D, far out or near', () => {
    expect(
      onOneSpot([
        [1, 2],
        [1, 2],
        [1, 2],
      ]),
    ).toBe(true);
    expect(
      onOneSpot([
        [1e6, -1e6, 3],
        [1e6, -1e6, 3],
      ]),
    ).toBe(true);
    expect(onOneSpot([])).toBe(true);
  });

  it('says no as soon as one point is apart, even a millionth apart', () => {
    expect(
      onOneSpot([
        [1, 2],
        [1, 2.000001],
      ]),
    ).toBe(false);
    expect(
      onOneSpot([
        [0, 0, 0],
        [0, 0, 0],
        [0, 0, 1e-6],
      ]),
    ).toBe(false);
  });

  it('is the same answer after moving every point by one offset (translation)', () => {
    fc.assert(
      fc.property(
        fc.array(fc.tuple(fc.integer({ min: -50, max: 50 }), fc.integer({ min: -50, max: 50 })), {
          minLength: 2,
          maxLength: 8,
        }),
        fc.tuple(fc.integer({ min: -1000, max: 1000 }), fc.integer({ min: -1000, max: 1000 })),
        (points, [dx, dy]) => {
          const moved = points.map(([x, y]) => [x + dx, y + dy]);
          expect(onOneSpot(moved)).toBe(onOneSpot(points));
          expect(onOneSpot(points)).toBe(
            points.every(([x, y]) => x === points[0][0] && y === points[0][1]),
          );
        },
      ),
    );
  });
});
