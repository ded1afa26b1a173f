import { describe, expect, it } from 'vitest';
import { splitBezier } from './bezier';
import { cubicSplineC2, quadraticSplineC1 } from './bezierSpline';
import { catmullRomSegments } from './catmullRom';
import { bezierJointContinuity } from './continuity';
import type { Point } from './vec';

const left: Point[] = [
  [0, 0],
  [1, 1],
  [2, 1],
  [3, 0],
];

describe('bezierJointContinuity', () => {
  it('is none when the segments do not meet', () => {
    expect(
      bezierJointContinuity(left, [
        [4, 0],
        [5, 1],
        [6, 0],
        [7, 0],
      ]),
    ).toBe('none');
  });

  it('is C0 at a corner', () => {
    expect(
      bezierJointContinuity(left, [
        [3, 0],
        [3, 1],
        [4, 1],
        [5, 0],
      ]),
    ).toBe('C0');
  });

  it('is G1 when the tangent directions agree but not the lengths', () => {
    expect(
      bezierJointContinuity(left, [
        [3, 0],
        [5, -2],
        [6, -2],
        [7, 0],
      ]),
    ).toBe('G1');
  });

  it('is C1 for a C¹ quadratic spline with a kink in curvature', () => {
    const [a, b] = quadraticSplineC1(
      [
        [0, 0],
        [2, 0],
        [4, 2],
      ],
      [1, 1],
    );
    expect(bezierJointContinuity(a, b)).toBe('C1');
  });

  it('is C2 for the natural cubic spline and for a subdivided curve', () => {
    const segments = cubicSplineC2([
      [0, 0],
      [1, 2],
      [3, 1],
      [4, 4],
    ]);
    expect(bezierJointContinuity(segments[0], segments[1])).toBe('C2');
    expect(bezierJointContinuity(segments[1], segments[2])).toBe('C2');
    const [first, second] = splitBezier(left, 0.5);
    // Halves of one curve: same geometry, but each half's parameter runs twice as fast.
    expect(bezierJointContinuity(first, second)).toBe('C2');
  });

  it('is G2 when curvature agrees but the speed does not', () => {
    // Right segment: the reversed-speed reparameterisation of a matching circle-like join.
    const a: Point[] = [
      [0, 0],
      [1, 0],
      [2, 0],
    ];
    const b: Point[] = [
      [2, 0],
      [4, 0],
      [6, 0],
    ];
    // Straight on both sides, speeds 2 and 4: curvature vectors both zero.
    expect(bezierJointContinuity(a, b)).toBe('G2');
  });

  it('is C1 for uniform Catmull-Rom but only G1 for centripetal and chordal with uneven spacing', () => {
    const points: Point[] = [
      [0, 0],
      [1, 0],
      [5, 3],
      [5.5, 7],
    ];
    const continuity = (alpha: number) => {
      const [a, b] = catmullRomSegments(points, alpha);
      return bezierJointContinuity(a, b);
    };
    expect(continuity(0)).toBe('C1');
    expect(continuity(0.5)).toBe('G1');
    expect(continuity(1)).toBe('G1');
  });

  it('respects the tolerance', () => {
    const nearly: Point[] = [
      [3, 1e-7],
      [3, 1],
      [4, 1],
      [5, 0],
    ];
    expect(bezierJointContinuity(left, nearly, 1e-9)).toBe('none');
    expect(bezierJointContinuity(left, nearly, 1e-6)).toBe('C0');
    expect(() => bezierJointContinuity(left, nearly, -1)).toThrow(/tolerance/);
    expect(() => bezierJointContinuity(left, [[3, 0, 0]])).toThrow(/3 coordinates but 2/);
  });
});
