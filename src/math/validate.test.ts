import { describe, expect, it } from 'vitest';
import { checkCoordinateArrays } from './checkCoordinateArrays';
import { checkPoint, checkPoints } from './checkPoints';
import {
  checkInteger,
  checkNumber,
  checkNumbers,
  checkOpenParameter,
  checkParameter,
  checkSameLength,
  copyCheckedNumbers,
} from './validate';
import type { Point } from './vec';

describe('input checks', () => {
  it('pass good input through and return what callers need', () => {
    expect(checkNumber('f', 'x', 2)).toBe(2);
    expect(checkInteger('f', 'n', 3, 0)).toBe(3);
    expect(checkParameter('f', 't', 1, 0, 1)).toBe(1);
    expect(checkOpenParameter('f', 'mu', 0.5, 0, 1)).toBe(0.5);
    expect(checkPoint('f', 'p', [1, 2, 3])).toBe(3);
    expect(
      checkPoints(
        'f',
        'points',
        [
          [1, 2],
          [3, 4],
        ],
        2,
      ),
    ).toBe(2);
    expect(checkPoints('f', 'points', [], 0)).toBe(0);
    expect(checkCoordinateArrays('f', [new Float64Array(3), new Float64Array(3)], 2)).toBe(3);
  });

  it('explain in words what was wrong and what is allowed', () => {
    expect(() => checkNumber('f', 'x', NaN)).toThrow('f: x is NaN; it must be a finite number.');
    expect(() => checkInteger('f', 'n', -1, 0)).toThrow(
      'f: n is -1; it must be a whole number ≥ 0.',
    );
    expect(() => checkParameter('f', 't', 2, 0, 1)).toThrow(
      'f: t = 2 is outside the allowed range [0, 1].',
    );
    expect(() => checkOpenParameter('f', 'mu', 1, 0, 1)).toThrow(
      'f: mu = 1 is outside the allowed range (0, 1), ends excluded.',
    );
    expect(() => checkPoints('f', 'points', [[0, 0]], 2)).toThrow(
      'f: points needs at least 2 points, but got 1.',
    );
    expect(() => checkPoints('f', 'points', [[0, 0], [1]], 1)).toThrow(
      'f: points[1] has 1 coordinates but points[0] has 2; every point must have the same dimension.',
    );
    expect(() =>
      checkPoints(
        'f',
        'points',
        [
          [0, 0],
          [1, Infinity],
        ],
        1,
      ),
    ).toThrow('f: points[1][1] is Infinity; every coordinate must be a finite number.');
    expect(() => checkPoint('f', 'p', 'a string' as unknown as Point)).toThrow(
      'f: p is a string; a point must be an array of coordinates such as [x, y].',
    );
    expect(() => checkNumbers('f', 'ys', [1, '2' as unknown as number], 1)).toThrow(
      'f: ys[1] is a string; every value must be a finite number.',
    );
    expect(() => checkSameLength('f', 'a', [1], 'b', [1, 2])).toThrow(
      'f: a has 1 entries but b has 2; they must match one for one.',
    );
    expect(() => checkCoordinateArrays('f', [new Float64Array(2)], 4)).toThrow(
      'f: needs at least 4 points, but got 2.',
    );
    expect(() => checkCoordinateArrays('f', [[1, 2] as unknown as Float64Array], 1)).toThrow(
      /not a Float64Array/,
    );
  });

  it('copy numbers into a Float64Array while checking them, with checkNumbers’ messages', () => {
    const values = [1, -2.5, 0];
    const copy = copyCheckedNumbers('f', 'ys', values, 1);
    expect(copy).toBeInstanceOf(Float64Array);
    expect(Array.from(copy)).toEqual(values);
    expect(copyCheckedNumbers('f', 'ys', [], 0)).toHaveLength(0);
    for (const bad of [[1, NaN], [1, Infinity], [1, '2'], [1, null], [1, undefined], [], 7, null]) {
      const message = (() => {
        try {
          checkNumbers('f', 'ys', bad as number[], 1);
        } catch (error) {
          return (error as Error).message;
        }
        return 'no error';
      })();
      expect(() => copyCheckedNumbers('f', 'ys', bad as number[], 1)).toThrow(message);
    }
  });

  it('throw RangeError', () => {
    expect(() => checkNumber('f', 'x', Infinity)).toThrow(RangeError);
  });
});
