import { describe, expect, it } from 'vitest';
import { buildKnotCurve, knotCursor } from './knotGeometry';

describe('the cursor at the end of the knot range', () => {
  it('at t = 1 sits on the domain’s end, not a rounding past it', () => {
    // u₀ + 1·(u₁ − u₀) = −8.831 + 9.561 = 0.7300000000000004 in doubles (worked in node),
    // past the last knot 0.73: the Cox–de Boor table refused it (the b-splines monkey, CI).
    const curve = buildKnotCurve({
      part: 'knots',
      points: [
        [0, 0],
        [1, 1],
      ],
      degree: 1,
      knots: [-8.831, -8.831, 0.73, 0.73],
      weights: [1, 1],
    });
    const cursor = knotCursor(curve, 1);
    expect(cursor.u).toBe(0.73);
    // A line at its end is its last point.
    expect(cursor.point[0]).toBeCloseTo(1, 12);
  });
});
