import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { nurbsCircle, nurbsPoint } from './nurbs';
import { projectiveMap } from './projectiveMap';
import { projectiveMapWeighted } from './projectiveNurbs';

const PERSPECTIVE = [
  [1, 0, 2],
  [0, 1, 0],
  [0.1, 0.2, 1],
];

describe('projectiveMapWeighted', () => {
  it('maps the points and multiplies each weight by its new w (by hand)', () => {
    // (1, 2): w = 0.1 + 0.4 + 1 = 1.5, image ((1 + 2)/1.5, 2/1.5) = (2, 4/3); weight 2 · 1.5 = 3.
    // (0, 0): w = 1, image (2, 0); weight 0.5 · 1 = 0.5.
    const { points, weights } = projectiveMapWeighted(
      PERSPECTIVE,
      [
        [1, 2],
        [0, 0],
      ],
      [2, 0.5],
    );
    expect(points[0][0]).toBeCloseTo(2, 15);
    expect(points[0][1]).toBeCloseTo(4 / 3, 15);
    expect(points[1]).toEqual([2, 0]);
    expect(weights[0]).toBeCloseTo(3, 15);
    expect(weights[1]).toBe(0.5);
  });

  it('an affine map leaves the weights as they are', () => {
    const affine = [
      [2, 1, 3],
      [0, 1, -1],
      [0, 0, 1],
    ];
    expect(projectiveMapWeighted(affine, [[1, 1]], [0.7]).weights).toEqual([0.7]);
  });

  it('the NURBS of the mapped points and weights is the mapped curve (the circle, any t)', () => {
    const circle = nurbsCircle([0, 0], 2);
    const image = projectiveMapWeighted(PERSPECTIVE, circle.points, circle.weights);
    fc.assert(
      fc.property(fc.double({ min: 0, max: 1, noNaN: true }), (t) => {
        const expected = projectiveMap(PERSPECTIVE, [
          nurbsPoint(circle.points, circle.weights, circle.knots, 2, t),
        ])[0];
        const got = nurbsPoint(image.points, image.weights, circle.knots, 2, t);
        return Math.hypot(got[0] - expected[0], got[1] - expected[1]) < 1e-12;
      }),
    );
  });

  it('refuses weights that do not match the points', () => {
    expect(() => projectiveMapWeighted(PERSPECTIVE, [[0, 0]], [1, 2])).toThrow(RangeError);
  });
});
