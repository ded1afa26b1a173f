import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, point } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { samplePlanarCubic } from './planarCubic';

// The lecture's cubic P0 = (0, 0), P1 = (1, 2), P2 = (3, 2), P3 = (4, 0).
const lectureCubic = [0, 0, 1, 2, 3, 2, 4, 0];

describe('samplePlanarCubic', () => {
  it('gives the lecture cubic at t = 0, 1/4, 1/2, 3/4, 1, worked by hand', () => {
    // t = 1/4: the weights (1 − t)³, 3(1 − t)²t, 3(1 − t)t², t³ are 27/64,
    // 27/64, 9/64, 1/64, so x = (27·1 + 9·3 + 1·4)/64 = 58/64 and
    // y = (27·2 + 9·2)/64 = 72/64. t = 1/2: 1/8, 3/8, 3/8, 1/8, so
    // x = (3 + 9 + 4)/8 = 2 and y = (6 + 6)/8 = 1.5. t = 3/4 mirrors t = 1/4
    // (the curve is symmetric about x = 2): x = 4 − 58/64 = 198/64.
    expect(Array.from(samplePlanarCubic(lectureCubic, 4))).toEqual([
      0, 0, 0.90625, 1.125, 2, 1.5, 3.09375, 1.125, 4, 0,
    ]);
  });

  it('starts exactly at P0 and ends exactly at P3', () => {
    const xy = samplePlanarCubic([0.1, 0.7, 5.3, -2.9, 1 / 3, 8.1, 2.2, 0.3], 12);
    expect([xy[0], xy[1]]).toEqual([0.1, 0.7]);
    expect([xy[24], xy[25]]).toEqual([2.2, 0.3]);
  });

  it('writes into the buffer it is given and returns it', () => {
    const out = new Float64Array(26);
    expect(samplePlanarCubic(lectureCubic, 12, out)).toBe(out);
    expect(samplePlanarCubic(lectureCubic, 2, out)).toBe(out);
    expect([out[2], out[3]]).toEqual([2, 1.5]);
  });

  it('allocates a buffer when the one given is too short', () => {
    const out = new Float64Array(4);
    const xy = samplePlanarCubic(lectureCubic, 2, out);
    expect(xy).not.toBe(out);
    expect(xy.length).toBe(6);
  });

  it('agrees with bezierPoint within rounding', () => {
    fc.assert(
      fc.property(
        fc.array(point(2), { minLength: 4, maxLength: 4 }),
        fc.integer({ min: 1, max: 64 }),
        (points, segments) => {
          const xy = samplePlanarCubic(points.flat(), segments);
          for (let i = 0; i <= segments; i++)
            expectClose([xy[2 * i], xy[2 * i + 1]], bezierPoint(points, i / segments));
        },
      ),
    );
  });

  it('sampled with one segment, is its two ends', () => {
    expect(Array.from(samplePlanarCubic(lectureCubic, 1))).toEqual([0, 0, 4, 0]);
  });

  it('refuses what is not a planar cubic, in words', () => {
    expect(() => samplePlanarCubic([0, 0, 1, 2, 3, 2, 4], 12)).toThrow(RangeError);
    expect(() => samplePlanarCubic([0, 0, 1, 2, 3, 2, 4, 0, 5], 12)).toThrow(/exactly 8/);
    expect(() => samplePlanarCubic([0, 0, 1, NaN, 3, 2, 4, 0], 12)).toThrow(/controls\[3\]/);
    expect(() => samplePlanarCubic(lectureCubic, 0)).toThrow(/segments/);
    expect(() => samplePlanarCubic(lectureCubic, 1.5)).toThrow(/segments/);
  });
});
