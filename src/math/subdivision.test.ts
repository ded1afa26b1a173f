import { describe, expect, it } from 'vitest';
import { subdivisionLevels } from './subdivision';
import type { Point } from './vec';

const cubic: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

describe('subdivisionLevels', () => {
  it('starts with the curve itself and doubles the pieces at each level', () => {
    const levels = subdivisionLevels(cubic, 0.5, 3);
    expect(levels.map((level) => level.length)).toEqual([1, 2, 4, 8]);
    expect(levels[0]).toEqual([cubic]);
  });

  it('splits the lecture cubic at ½ into the de Casteljau polygons', () => {
    // Level 1: (½, 1), (2, 2), (3½, 1); level 2: (1¼, 1½), (2¾, 1½); level 3: (2, 1½).
    const [left, right] = subdivisionLevels(cubic, 0.5, 1)[1];
    expect(left).toEqual([
      [0, 0],
      [0.5, 1],
      [1.25, 1.5],
      [2, 1.5],
    ]);
    expect(right).toEqual([
      [2, 1.5],
      [2.75, 1.5],
      [3.5, 1],
      [4, 0],
    ]);
  });

  it('joins the pieces end to end, from P0 to Pn', () => {
    const pieces = subdivisionLevels(cubic, 0.3, 2)[2];
    expect(pieces[0][0]).toEqual([0, 0]);
    expect(pieces[3][3]).toEqual([4, 0]);
    for (let j = 1; j < pieces.length; j++) expect(pieces[j][0]).toEqual(pieces[j - 1][3]);
  });

  it('refuses a negative number of levels', () => {
    expect(() => subdivisionLevels(cubic, 0.5, -1)).toThrow(RangeError);
  });
});
