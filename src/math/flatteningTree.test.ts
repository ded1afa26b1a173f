import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { polygon } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { flattenBezier } from './flatten';
import { flatteningTree } from './flatteningTree';

// Flatness of the parabola (0,0), (1,2), (2,0): n(n−1)/8 · ‖Δ²P‖ = 2/8 · ‖(0, −4)‖ = 1;
// each halving divides the second differences by 4.
const PARABOLA = [
  [0, 0],
  [1, 2],
  [2, 0],
];

describe('flatteningTree', () => {
  it('the parabola within 1 is one piece', () => {
    const tree = flatteningTree(PARABOLA, 1);
    expect(tree).toHaveLength(1);
    expect(tree[0]).toMatchObject({ depth: 0, t0: 0, t1: 1, flatness: 1, split: false });
  });

  it('within ½: split once, the halves have flatness ¼', () => {
    const tree = flatteningTree(PARABOLA, 0.5);
    expect(tree.map((n) => [n.parent, n.depth, n.t0, n.t1, n.flatness, n.split])).toEqual([
      [-1, 0, 0, 1, 1, true],
      [0, 1, 0, 0.5, 0.25, false],
      [0, 1, 0.5, 1, 0.25, false],
    ]);
    expect(tree[1].points).toEqual([
      [0, 0],
      [0.5, 1],
      [1, 1],
    ]);
  });

  it('within 0.2: seven pieces, four leaves of flatness 1/16, left first', () => {
    const tree = flatteningTree(PARABOLA, 0.2);
    expect(tree.map((n) => n.t0)).toEqual([0, 0, 0, 0.25, 0.5, 0.5, 0.75]);
    expect(tree.filter((n) => !n.split).map((n) => n.flatness)).toEqual([
      1 / 16,
      1 / 16,
      1 / 16,
      1 / 16,
    ]);
  });

  it('its leaves are exactly flattenBezier’s polyline, and each leaf is de Casteljau’s piece', () => {
    fc.assert(
      fc.property(polygon(2, 7), fc.double({ min: 0.5, max: 50, noNaN: true }), (points, tol) => {
        const tree = flatteningTree(points, tol);
        const leaves = tree.filter((n) => !n.split);
        const polyline = flattenBezier(points, tol);
        expect([leaves[0].points[0], ...leaves.map((n) => n.points[n.points.length - 1])]).toEqual(
          polyline,
        );
        for (const leaf of leaves) {
          const start = bezierPoint(points, leaf.t0);
          for (let d = 0; d < start.length; d++)
            expect(leaf.points[0][d]).toBeCloseTo(start[d], 6 - Math.log10(1 + Math.abs(start[d])));
        }
        // The leaves tile [0, 1] in order.
        leaves.forEach((leaf, k) => expect(leaf.t0).toBe(k === 0 ? 0 : leaves[k - 1].t1));
        expect(leaves[leaves.length - 1].t1).toBe(1);
      }),
      { numRuns: 40 },
    );
  });
});
