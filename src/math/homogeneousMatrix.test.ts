import { describe, expect, it } from 'vitest';
import { homogeneousWeight, multiplyPlaneMatrices, translationMatrix } from './homogeneousMatrix';
import { projectiveMap } from './projectiveMap';

describe('plane matrices', () => {
  it('compose right to left: rotate a quarter turn about (1, 1)', () => {
    const quarter = [
      [0, -1, 0],
      [1, 0, 0],
      [0, 0, 1],
    ];
    const about = multiplyPlaneMatrices(
      translationMatrix(1, 1),
      multiplyPlaneMatrices(quarter, translationMatrix(-1, -1)),
    );
    // (2, 1) is one unit right of the centre; a quarter turn puts it one unit above: (1, 2).
    expect(about).toEqual([
      [0, -1, 2],
      [1, 0, 0],
      [0, 0, 1],
    ]);
    expect(projectiveMap(about, [[2, 1]])).toEqual([[1, 2]]);
  });

  it('gives w = 1 for an affine map and the last row at the point for a perspective one', () => {
    expect(homogeneousWeight(translationMatrix(5, -3), [7, 8])).toBe(1);
    const perspective = [
      [1, 0, 0],
      [0, 1, 0],
      [0.5, 0.25, 1],
    ];
    // 0.5·2 + 0.25·4 + 1 = 3.
    expect(homogeneousWeight(perspective, [2, 4])).toBe(3);
  });

  it('refuses a matrix that is not 3 × 3', () => {
    expect(() => multiplyPlaneMatrices([[1, 0, 0]], translationMatrix(0, 0))).toThrow(RangeError);
  });
});
