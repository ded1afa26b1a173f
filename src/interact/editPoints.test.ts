import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Point } from '../math';
import { distanceToSegment, extendPolygon, insertPoint } from './editPoints';

type Point2 = Point;

const square: Point2[] = [
  [0, 0],
  [4, 0],
  [4, 4],
];

describe('insertPoint', () => {
  it('puts a point into the nearest edge', () => {
    expect(insertPoint(square, [2, -0.5])).toEqual([
      [0, 0],
      [2, -0.5],
      [4, 0],
      [4, 4],
    ]);
    expect(insertPoint(square, [4.5, 2])).toEqual([
      [0, 0],
      [4, 0],
      [4.5, 2],
      [4, 4],
    ]);
  });

  it('goes before the first or after the last point when that is nearer', () => {
    expect(insertPoint(square, [-2, -1])).toEqual([[-2, -1], ...square]);
    expect(insertPoint(square, [4, 7])).toEqual([...square, [4, 7]]);
    expect(insertPoint([], [1, 1])).toEqual([[1, 1]]);
  });

  it('keeps every old point, in order, and never changes its input', () => {
    const coordinate = fc.double({ min: -100, max: 100, noNaN: true });
    const point = fc.tuple(coordinate, coordinate) as fc.Arbitrary<Point2>;
    fc.assert(
      fc.property(fc.array(point, { minLength: 0, maxLength: 12 }), point, (points, at) => {
        const copy = points.map((p) => [...p]);
        const result = insertPoint(points, at);
        expect(result).toHaveLength(points.length + 1);
        expect(result.filter((p) => p !== at)).toEqual(points);
        expect(points).toEqual(copy);
      }),
    );
  });
});

describe('extendPolygon', () => {
  it('continues the last edge at 70 % and turns a little left', () => {
    expect(
      extendPolygon([
        [0, 0],
        [2, 0],
      ]),
    ).toEqual([3.4, 0.5]);
  });

  it('copes with a repeated last point and with a single point', () => {
    expect(
      extendPolygon([
        [1, 1],
        [1, 1],
      ]),
    ).toEqual([1.7, 1.25]);
    expect(extendPolygon([[1, 1]])).toEqual([1.7, 1.25]);
  });
});

describe('distanceToSegment', () => {
  it('measures to the nearest point of the segment, ends included', () => {
    expect(distanceToSegment([1, 1], [0, 0], [2, 0])).toBe(1);
    expect(distanceToSegment([5, 4], [0, 0], [2, 0])).toBe(5);
    expect(distanceToSegment([3, 4], [0, 0], [0, 0])).toBe(5);
  });
});
