import { Bezier } from 'bezier-js';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { polygon, polygon2D } from './arbitraries.test-helpers';
import { arcLengthByPolyline } from './arcLength.test-helpers';
import { bezierArcLength } from './arcLength';
import type { Point } from './vec';

describe('bezierArcLength', () => {
  it('is the chord for a straight line, whatever the speed', () => {
    expect(
      bezierArcLength([
        [0, 0],
        [3, 4],
      ]),
    ).toBeCloseTo(5, 12);
    expect(
      bezierArcLength([
        [0, 0],
        [0.1, 0],
        [2.9, 0],
        [3, 0],
      ]),
    ).toBeCloseTo(3, 10);
  });

  it('matches the closed form for the parabola y = x² from 0 to 1', () => {
    // x = t, y = t²: ∫ √(1 + 4t²) dt = √5/2 + asinh(2)/4.
    const parabola: Point[] = [
      [0, 0],
      [0.5, 0],
      [1, 1],
    ];
    expect(bezierArcLength(parabola)).toBeCloseTo(Math.sqrt(5) / 2 + Math.asinh(2) / 4, 12);
    // Up to t = 1/2: [t√(1+4t²)/2 + asinh(2t)/4] at 1/2.
    expect(bezierArcLength(parabola, 0.5)).toBeCloseTo(
      (0.5 * Math.SQRT2) / 2 + Math.asinh(1) / 4,
      12,
    );
  });

  it('agrees with bezier-js and with a fine polyline', () => {
    fc.assert(
      fc.property(polygon2D(4, 4), (points) => {
        const ours = bezierArcLength(points);
        const reference = new Bezier(points.map(([x, y]) => ({ x, y }))).length();
        const fine = arcLengthByPolyline(points, 20000);
        expect(Math.abs(ours - fine)).toBeLessThanOrEqual(1e-6 * Math.max(1, fine));
        // bezier-js uses a fixed 24-point rule, less accurate near cusps.
        expect(Math.abs(ours - reference)).toBeLessThanOrEqual(1e-2 * Math.max(1, fine));
      }),
    );
  });

  it('works in 3D and is additive along the curve', () => {
    fc.assert(
      fc.property(polygon(2, 6), fc.double({ min: 0, max: 1, noNaN: true }), (points, t) => {
        const total = bezierArcLength(points);
        const part = bezierArcLength(points, t);
        expect(part).toBeLessThanOrEqual(total * (1 + 1e-9) + 1e-9);
        expect(Math.abs(total - arcLengthByPolyline(points, 4000))).toBeLessThanOrEqual(
          1e-4 * Math.max(1, total),
        );
      }),
    );
  });

  it('scales exactly, from 1e-300 to 1e300 (no underflow, no overflow)', () => {
    // fast-check found coordinates near 1e-300 on which the tolerance underflowed
    // and bisection ran for minutes.
    const curve: Point[] = [
      [0, 0],
      [1, 2],
      [3, -1],
      [4, 0.5],
    ];
    const length = bezierArcLength(curve);
    for (const k of [1e-300, 1e-200, 1e-12, 1e12, 1e200, 1e300]) {
      const scaled = bezierArcLength(curve.map((p) => p.map((v) => v * k)));
      expect(Math.abs(scaled / k - length)).toBeLessThanOrEqual(1e-12 * length);
    }
    const found: Point[] = [
      [-6.750656998894163e-179, -1.1716973534879419e-185],
      [2.480871621883356e-226, 4.606909187070027e-161],
      [1.388963649242084e-306, -2.814317881242241e-235],
    ];
    const tiny = bezierArcLength(found);
    const lifted = bezierArcLength(found.map((p) => p.map((v) => v * 1e160))) / 1e160;
    expect(tiny).toBeGreaterThan(0);
    expect(Math.abs(tiny - lifted)).toBeLessThanOrEqual(1e-9 * lifted);
  });

  it('is 0 for a point and rejects bad arguments', () => {
    expect(bezierArcLength([[1, 2]])).toBe(0);
    expect(() =>
      bezierArcLength(
        [
          [0, 0],
          [1, 1],
        ],
        2,
      ),
    ).toThrow(/upTo = 2 is outside/);
    expect(() =>
      bezierArcLength(
        [
          [0, 0],
          [1, 1],
        ],
        1,
        0,
      ),
    ).toThrow(/tolerance/);
  });
});
