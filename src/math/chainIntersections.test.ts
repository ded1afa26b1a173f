import { describe, expect, it } from 'vitest';
import { catmullRomSegments } from './catmullRom';
import { bezierChainSelfIntersections } from './chainIntersections';

describe('bezierChainSelfIntersections', () => {
  it('finds the loop of one piece and none on a simple arc', () => {
    expect(
      bezierChainSelfIntersections([
        [
          [0, 0],
          [5, 3],
          [-1, 3],
          [4, 0],
        ],
      ]),
    ).toHaveLength(1);
    expect(
      bezierChainSelfIntersections([
        [
          [0, 0],
          [1, 2],
          [3, 2],
          [4, 0],
        ],
      ]),
    ).toEqual([]);
  });
  it('finds two pieces that cross, not neighbours that touch', () => {
    const crossing = bezierChainSelfIntersections([
      [
        [0, 0],
        [1, 0],
        [2, 0],
        [3, 0],
      ],
      [
        [3, 0],
        [3, 1],
        [3, 2],
        [3, 3],
      ],
      [
        [2, 3],
        [2, 2],
        [2, 1],
        [2, -1],
      ],
    ]);
    expect(crossing).toHaveLength(1);
    expect(crossing[0][0]).toBeCloseTo(2, 9);
    expect(crossing[0][1]).toBeCloseTo(0, 9);
  });
  it('the hairpin: uniform Catmull-Rom loops, centripetal and chordal do not', () => {
    const hairpin = [
      [0, 0],
      [3, 1],
      [3, 1.2],
      [0, 2.5],
    ];
    expect(bezierChainSelfIntersections(catmullRomSegments(hairpin, 0)).length).toBeGreaterThan(0);
    expect(bezierChainSelfIntersections(catmullRomSegments(hairpin, 0.5))).toEqual([]);
    expect(bezierChainSelfIntersections(catmullRomSegments(hairpin, 1))).toEqual([]);
  });
});
