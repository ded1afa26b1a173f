import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bezierJointReport, snapJoint } from './jointReport';

const left = [
  [0, 0],
  [1, 1],
  [2, 1],
  [3, 0],
];

describe('bezierJointReport', () => {
  it('reads C² with its numbers where the control points continue the polygon', () => {
    // Right piece mirrors the left: P′ = 3(3 − 2, 0 − 1) = (3, −3) on both sides;
    // P″ = 6(1 − 4 + 3, 1 − 2 + 0) = (0, −6) at the end, 6(3 − 8 + 5, 0 + 2 − 3) at the start.
    const report = bezierJointReport(left, [
      [3, 0],
      [4, -1],
      [5, -3],
      [6, -6],
    ]);
    expect(report.continuity).toBe('C2');
    expect(report.leftVelocity).toEqual([3, -3]);
    expect(report.rightVelocity).toEqual([3, -3]);
    expect(report.leftSecond).toEqual([0, -6]);
    expect(report.rightSecond).toEqual([0, -6]);
    expect(report.angle).toBeCloseTo(0, 9);
    expect(report.lengthRatio).toBe(1);
    // κ = (x′y″ − y′x″)/|P′|³ = (3·(−6) − 0)/(√18)³ = −18/(18√18) = −1/√18.
    expect(report.leftCurvature).toBeCloseTo(-1 / Math.sqrt(18), 12);
  });

  it('reads G¹ with length ratio 2 where the next control point is twice as far on the line', () => {
    const report = bezierJointReport(left, [
      [3, 0],
      [5, -2],
      [6, -2],
      [7, 0],
    ]);
    expect(report.continuity).toBe('G1');
    expect(report.lengthRatio).toBeCloseTo(2, 12);
    expect(report.angle).toBeCloseTo(0, 6);
  });

  it('reads a 90° corner as C⁰', () => {
    const report = bezierJointReport(left, [
      [3, 0],
      [4, 1],
      [5, 1],
      [6, 0],
    ]);
    expect(report.continuity).toBe('C0');
    expect(report.angle).toBeCloseTo(90, 9);
  });

  it('reads a corner made by control points on the joint (as fonts do) as C⁰, although both velocities are zero', () => {
    const report = bezierJointReport(
      [
        [0, 0],
        [1, 1],
        [3, 0],
        [3, 0],
      ],
      [
        [3, 0],
        [3, 0],
        [4, 2],
        [5, 2],
      ],
    );
    expect(report.degenerate).toBe(true);
    expect(report.leftVelocity).toEqual([0, 0]);
    expect(report.continuity).toBe('C0');
    // A zero velocity has no direction and no length: no angle, no ratio, no curvature.
    expect(report.angle).toBeNaN();
    expect(report.lengthRatio).toBeNaN();
    expect(report.leftCurvature).toBeNaN();
    expect(report.rightCurvature).toBeNaN();
  });
});

describe('snapJoint', () => {
  const coordinate = fc.double({ min: -50, max: 50, noNaN: true });
  const point = fc.tuple(coordinate, coordinate).map(([x, y]) => [x, y]);
  it('Make C¹ mirrors the point before: the joint becomes C¹ or better', () => {
    fc.assert(
      fc.property(point, point, point, point, (a, b, c, e) => {
        fc.pre(Math.hypot(c[0] - b[0], c[1] - b[1]) > 1e-3);
        const after = snapJoint(b, c, [0, 0], 'C1');
        const report = bezierJointReport([a, a, b, c], [c, after, e, e], 1e-7);
        expect(['C1', 'G2', 'C2']).toContain(report.continuity);
      }),
    );
  });
  it('Make G¹ keeps the distance: G¹ but not C¹ when the two lengths differ', () => {
    const after = snapJoint([2, 1], [3, 0], [3, 2], 'G1');
    expect(after[0]).toBeCloseTo(3 + Math.SQRT2, 12);
    expect(after[1]).toBeCloseTo(-Math.SQRT2, 12);
    const report = bezierJointReport(left, [[3, 0], after, [6, -3], [7, 0]]);
    expect(report.continuity).toBe('G1');
  });
});
