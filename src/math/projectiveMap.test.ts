import { describe, expect, it } from 'vitest';
import { expectClose } from './arbitraries.test-helpers';
import { projectiveMap } from './projectiveMap';

describe('projectiveMap', () => {
  it('applies an affine map: rotation by 90° then a shift', () => {
    const matrix = [
      [0, -1, 5],
      [1, 0, 0],
      [0, 0, 1],
    ];
    const [a, b] = projectiveMap(matrix, [
      [1, 0],
      [2, 3],
    ]);
    expect(a).toEqual([5, 1]);
    expect(b).toEqual([2, 2]);
  });

  it('divides by w for a perspective map', () => {
    const matrix = [
      [1, 0, 0],
      [0, 1, 0],
      [0.5, 0, 1],
    ];
    // w = 0.5·2 + 1 = 2
    expectClose(projectiveMap(matrix, [[2, 4]])[0], [1, 2]);
  });

  it('refuses points on or beyond the vanishing line, saying which', () => {
    const matrix = [
      [1, 0, 0],
      [0, 1, 0],
      [-1, 0, 1],
    ];
    expect(() =>
      projectiveMap(matrix, [
        [0, 0],
        [1, 0],
      ]),
    ).toThrow(/points\[1\]/);
    expect(() => projectiveMap(matrix, [[2, 0]])).toThrow(RangeError);
  });

  it('rejects a malformed matrix', () => {
    expect(() => projectiveMap([[1, 0, 0]], [[0, 0]])).toThrow(RangeError);
    expect(() =>
      projectiveMap(
        [
          [1, 0, 0],
          [0, NaN, 0],
          [0, 0, 1],
        ],
        [[0, 0]],
      ),
    ).toThrow(RangeError);
  });
});
