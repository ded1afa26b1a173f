import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { polygon2D } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { chordDeviation } from './chordDeviation';
import { flattenBezier } from './flatten';
import { flatteningTree } from './flatteningTree';
import { uniformCountEstimate, uniformCountWithin, uniformParameters } from './uniformCount';

// The parabola P(t) = (2t, 4t(1 − t)) of the control points (0,0), (1,2), (2,0).
const PARABOLA = [
  [0, 0],
  [1, 2],
  [2, 0],
];

describe('chordDeviation', () => {
  it('one chord under the parabola: the apex, 1 above the x axis at t = ½', () => {
    const d = chordDeviation(PARABOLA, [0, 1]);
    expect(d.distance).toBeCloseTo(1, 12);
    expect(d.t).toBeCloseTo(0.5, 6);
    expect(d.piece).toBe(0);
    expect(d.foot[0]).toBeCloseTo(1, 6);
    expect(d.foot[1]).toBeCloseTo(0, 12);
  });

  it('two chords: |2t − 4t²|/√2 from the line y = x, largest at t = ¼: 1/(4√2)', () => {
    const d = chordDeviation(PARABOLA, uniformParameters(2));
    expect(d.distance).toBeCloseTo(1 / (4 * Math.SQRT2), 12);
    // Both pieces are mirror images: the first one is reported.
    expect(d.t).toBeCloseTo(0.25, 6);
    expect(d.piece).toBe(0);
  });

  it('a straight curve never leaves its chords', () => {
    const line = [
      [0, 0],
      [1, 1],
      [3, 3],
    ];
    expect(chordDeviation(line, uniformParameters(3)).distance).toBeLessThan(1e-12);
  });

  it('the deviation of a vertical gap: h² for the parabola over a piece of length h in t', () => {
    // Pieces of length ¼ of y = 4t(1 − t) sag h²·|y″|/8 = 1/16 below their chords
    // vertically; the chord's slope makes the perpendicular gap shorter.
    const d = chordDeviation(PARABOLA, uniformParameters(4));
    expect(d.distance).toBeLessThanOrEqual(1 / 16 + 1e-15);
    // The flattest chords (the middle ones) have slope ±½: gap (1/16)·2/√5.
    expect(d.distance).toBeGreaterThanOrEqual((1 / 16) * (2 / Math.sqrt(5)) - 1e-12);
  });

  it('uniform counts for the parabola: 1 chord within 1, 2 within 0.2', () => {
    expect(uniformCountWithin(PARABOLA, 1)).toBe(1);
    expect(uniformCountWithin(PARABOLA, 0.2)).toBe(2);
    expect(uniformCountWithin(PARABOLA, 0.17)).toBe(3);
  });

  it('is at least the gap at every sampled parameter, and flattening keeps it within the tolerance', () => {
    fc.assert(
      fc.property(
        polygon2D(2, 6),
        fc.double({ min: 0.5, max: 20, noNaN: true }),
        (points, tolerance) => {
          const tree = flatteningTree(points, tolerance);
          const leaves = tree.filter((node) => !node.split);
          const parameters = [0, ...leaves.map((node) => node.t1)];
          const d = chordDeviation(points, parameters);
          if (!leaves.some((node) => node.cut)) {
            expect(d.distance).toBeLessThanOrEqual(tolerance * (1 + 1e-9));
          }
          const polyline = flattenBezier(points, tolerance);
          expect(polyline).toHaveLength(parameters.length);
          for (let s = 1; s < 20; s++) {
            const p = bezierPoint(points, s / 20);
            const k = parameters.findIndex((t) => t >= s / 20) - 1;
            const a = bezierPoint(points, parameters[Math.max(0, k)]);
            const b = bezierPoint(points, parameters[Math.max(1, k + 1)]);
            // Distance to the chord's line is at most the distance to the chord.
            const cross = Math.abs((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]));
            const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
            if (length > 1e-9)
              expect(cross / length).toBeLessThanOrEqual(d.distance * (1 + 1e-9) + 1e-9);
          }
        },
      ),
      { numRuns: 40 },
    );
  });

  it('skipping pieces by their control points changes nothing: the same piece, gap and t as measuring each piece alone', () => {
    fc.assert(
      fc.property(
        polygon2D(2, 8),
        fc.array(fc.double({ min: 0.01, max: 1, noNaN: true }), { minLength: 1, maxLength: 12 }),
        (points, lengths) => {
          // Increasing parameters from 0 to 1 with the given relative lengths.
          const total = lengths.reduce((a, b) => a + b, 0);
          const parameters = [0];
          for (const length of lengths)
            parameters.push(parameters[parameters.length - 1] + length / total);
          parameters[parameters.length - 1] = 1;
          if (parameters.some((t, k) => k > 0 && !(t > parameters[k - 1]))) return;
          const each = parameters
            .slice(1)
            .map((t1, k) => chordDeviation(points, [parameters[k], t1]).distance);
          const largest = Math.max(...each);
          const d = chordDeviation(points, parameters);
          expect(d.distance).toBe(largest);
          expect(d.piece).toBe(each.indexOf(largest));
        },
      ),
      { numRuns: 60 },
    );
  });

  it('the estimate √(max‖P″⊥‖ / 8τ): the parabola has P″ = 2·(P2 − 2P1 + P0) = (0, −8), all across the tangent (2, 0) at t = ½', () => {
    // n = ⌈√(8 / 8τ)⌉ = ⌈1/√τ⌉.
    expect(uniformCountEstimate(PARABOLA, 1)).toBe(1);
    expect(uniformCountEstimate(PARABOLA, 1 / 16)).toBe(4);
    expect(uniformCountEstimate(PARABOLA, 0.01)).toBe(10);
    expect(uniformCountEstimate(PARABOLA, 0.0099)).toBe(11);
    // The same parabola as a cubic (degree elevated: Qi = i/3·P(i−1) + (1 − i/3)·Pi).
    const cubic = [
      [0, 0],
      [2 / 3, 4 / 3],
      [4 / 3, 4 / 3],
      [2, 0],
    ];
    expect(uniformCountEstimate(cubic, 0.01)).toBe(10);
    // Speeding up along a straight line, P″ ∥ P′: one segment, however fast.
    const ray = [
      [0, 0],
      [0, 0],
      [1000, 1000],
    ];
    expect(uniformCountEstimate(ray, 0.001)).toBe(1);
    expect(uniformCountWithin(ray, 0.001)).toBe(1);
    expect(
      uniformCountEstimate(
        [
          [0, 0],
          [5, 5],
        ],
        0.1,
      ),
    ).toBe(1);
    expect(() => uniformCountEstimate(PARABOLA, 0)).toThrow(RangeError);
  });

  it('the parabola within 1/16: 4 segments (chords sloped ±½ or ±3/2, gaps (1/16)·2/√5), not 3 (the middle chord is level, gap 1/9)', () => {
    expect(uniformCountWithin(PARABOLA, 1 / 16)).toBe(4);
    expect(uniformCountWithin(PARABOLA, 1 / 9)).toBe(3);
  });

  it('says "more than the maximum" instead of searching past it', () => {
    // About 1/n² for n segments: 1e-8 needs about 10 000, far above 512.
    expect(uniformCountWithin(PARABOLA, 1e-8, 512)).toBe(513);
    expect(uniformCountWithin(PARABOLA, 1 / 16, 3)).toBe(4);
    expect(uniformCountWithin(PARABOLA, 1 / 16, 4)).toBe(4);
  });

  it('the count found reaches the tolerance and one segment fewer does not, whenever it is within the maximum', () => {
    fc.assert(
      fc.property(
        polygon2D(2, 7),
        fc.double({ min: 0.01, max: 20, noNaN: true }),
        (points, tolerance) => {
          const count = uniformCountWithin(points, tolerance, 256);
          const gap = (n: number) => chordDeviation(points, uniformParameters(n)).distance;
          if (count > 256) {
            expect(gap(256)).toBeGreaterThan(tolerance);
            return;
          }
          expect(gap(count)).toBeLessThanOrEqual(tolerance);
          if (count > 1) expect(gap(count - 1)).toBeGreaterThan(tolerance);
        },
      ),
      { numRuns: 60 },
    );
  });

  it('refuses parameters that do not increase', () => {
    expect(() => chordDeviation(PARABOLA, [0, 0.5, 0.5, 1])).toThrow(RangeError);
    expect(() => chordDeviation(PARABOLA, [0])).toThrow(RangeError);
  });
});
