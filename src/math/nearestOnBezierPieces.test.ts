import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { bezierPieceBoxes, nearestOnBezierPieces } from './nearestOnBezierPieces';
import type { Point } from './vec';

/** Two segments: along the x axis to (2, 0), then up to (2, 2). */
const corner: Point[][] = [
  [
    [0, 0],
    [2, 0],
  ],
  [
    [2, 0],
    [2, 2],
  ],
];

describe('nearestOnBezierPieces', () => {
  it('drops a perpendicular onto a segment: (1, 3) onto (0, 0)–(4, 0) at t = ¼', () => {
    const near = nearestOnBezierPieces(
      [
        [
          [0, 0],
          [4, 0],
        ],
      ],
      [1, 3],
    )!;
    expect(near.piece).toBe(0);
    expect(near.t).toBeCloseTo(0.25, 12);
    expectClose(near.point, [1, 0], 1e-12);
    expect(near.distance).toBeCloseTo(3, 12);
  });

  it('stops at the end when the perpendicular falls beyond it', () => {
    const near = nearestOnBezierPieces(
      [
        [
          [0, 0],
          [4, 0],
        ],
      ],
      [6, 1],
    )!;
    expect(near).toEqual({ piece: 0, t: 1, point: [4, 0], distance: Math.sqrt(5) });
  });

  it('finds t = ½ on the straight cubic B(t) = (3t, 0) below (1.5, 2)', () => {
    const cubic = [
      [0, 0],
      [1, 0],
      [2, 0],
      [3, 0],
    ];
    const near = nearestOnBezierPieces([cubic], [1.5, 2])!;
    expect(near.t).toBeCloseTo(0.5, 12);
    expect(near.distance).toBeCloseTo(2, 12);
  });

  it('finds the vertex of the parabola y = x² (control points (−1, 1), (0, −1), (1, 1)) below (0, ½)', () => {
    // x(t) = 2t − 1, y(t) = (2t − 1)²: the distance² from (0, ½) is x⁴ + ¼, least at x = 0.
    const near = nearestOnBezierPieces(
      [
        [
          [-1, 1],
          [0, -1],
          [1, 1],
        ],
      ],
      [0, 0.5],
    )!;
    expect(near.t).toBeCloseTo(0.5, 12);
    expectClose(near.point, [0, 0], 1e-12);
    expect(near.distance).toBeCloseTo(0.5, 12);
  });

  it('picks the right piece of a chain, and the earlier piece at a joint', () => {
    const side = nearestOnBezierPieces(corner, [3, 1])!;
    expect(side.piece).toBe(1);
    expect(side.t).toBeCloseTo(0.5, 12);
    expect(side.distance).toBeCloseTo(1, 12);
    // (3, −1) is nearest to the joint (2, 0): the end of piece 0 and the start of piece 1.
    expect(nearestOnBezierPieces(corner, [3, -1])).toEqual({
      piece: 0,
      t: 1,
      point: [2, 0],
      distance: Math.SQRT2,
    });
  });

  it('gives null for no pieces and for nothing within reach', () => {
    expect(nearestOnBezierPieces([], [0, 0])).toBeNull();
    // (1, 5) is √10 from (2, 2), the nearest point of the corner.
    expect(nearestOnBezierPieces(corner, [1, 5], { within: 3 })).toBeNull();
    expect(nearestOnBezierPieces(corner, [1, 5], { within: 4 })).toEqual({
      piece: 1,
      t: 1,
      point: [2, 2],
      distance: Math.sqrt(10),
    });
  });

  it('takes t = 0 on a piece that is a single spot', () => {
    const spot = [
      [1, 1],
      [1, 1],
      [1, 1],
      [1, 1],
    ];
    expect(nearestOnBezierPieces([spot], [4, 5])).toEqual({
      piece: 0,
      t: 0,
      point: [1, 1],
      distance: 5,
    });
  });

  it('words what is wrong', () => {
    expect(() => nearestOnBezierPieces(corner, [1])).toThrow(RangeError);
    expect(() => nearestOnBezierPieces(corner, [1, 2], { boxes: new Float64Array(3) })).toThrow(
      /bezierPieceBoxes/,
    );
    expect(() => bezierPieceBoxes([[[0, 0]], [[0, 0, 0]]])).toThrow(RangeError);
  });

  const piece = fc
    .integer({ min: 2, max: 4 })
    .chain((count) => fc.array(point(2), { minLength: count, maxLength: count }));
  const chain = fc.array(piece, { minLength: 1, maxLength: 4 });

  it('is no farther than any sampled point of the chain, and is the point it names', () => {
    fc.assert(
      fc.property(chain, point(2), (pieces, at) => {
        const near = nearestOnBezierPieces(pieces, at)!;
        expectClose(near.point, bezierPoint(pieces[near.piece], near.t), 1e-9);
        expect(near.distance).toBeCloseTo(
          Math.hypot(near.point[0] - at[0], near.point[1] - at[1]),
          9,
        );
        const scale = Math.max(1, ...pieces.flat(2).map(Math.abs), ...at.map(Math.abs));
        let sampled = Infinity;
        for (const curve of pieces) {
          for (let k = 0; k <= 200; k++) {
            const p = bezierPoint(curve, k / 200);
            sampled = Math.min(sampled, Math.hypot(p[0] - at[0], p[1] - at[1]));
          }
        }
        expect(near.distance).toBeLessThanOrEqual(sampled + 1e-9 * scale);
      }),
    );
  });

  it('gives the same answer with the boxes, which only skip pieces', () => {
    fc.assert(
      fc.property(chain, point(2), (pieces, at) => {
        const plain = nearestOnBezierPieces(pieces, at)!;
        const boxed = nearestOnBezierPieces(pieces, at, { boxes: bezierPieceBoxes(pieces) })!;
        expect(boxed).toEqual(plain);
      }),
    );
  });
});

describe('bezierPieceBoxes', () => {
  it('holds each piece between the least and greatest of its control points', () => {
    expect([...bezierPieceBoxes(corner)]).toEqual([0, 0, 2, 0, 2, 0, 2, 2]);
  });
});
