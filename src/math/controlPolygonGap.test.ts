import { describe, expect, it } from 'vitest';
import { elevateDegree, splitBezier } from './bezier';
import { controlPolygonGap } from './controlPolygonGap';
import type { Point } from './vec';

const cubic: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

describe('controlPolygonGap', () => {
  it('is |P1 − P(1/3)| for the lecture cubic', () => {
    // P(1/3) = (8/27)(0,0) + (12/27)(1,2) + (6/27)(3,2) + (1/27)(4,0) = (34/27, 36/27)
    expect(controlPolygonGap(cubic)).toBeCloseTo(Math.hypot(1 - 34 / 27, 2 - 36 / 27), 12);
  });

  it('is zero for a straight line with evenly spaced points and for one point', () => {
    expect(
      controlPolygonGap([
        [0, 0],
        [1, 1],
        [2, 2],
      ]),
    ).toBeCloseTo(0, 14);
    expect(controlPolygonGap([[3, 4]])).toBe(0);
  });

  it('shrinks under repeated degree elevation and subdivision', () => {
    let elevated = cubic;
    const gaps = [controlPolygonGap(elevated)];
    for (let k = 0; k < 6; k++) {
      elevated = elevateDegree(elevated);
      gaps.push(controlPolygonGap(elevated));
    }
    for (let k = 1; k < gaps.length; k++) expect(gaps[k]).toBeLessThan(gaps[k - 1]);
    const [left] = splitBezier(cubic, 0.5);
    expect(controlPolygonGap(left)).toBeLessThan(controlPolygonGap(cubic) / 2);
  });
});
