import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { segmentCoverage } from './strokeCoverage';

describe('segmentCoverage', () => {
  it('a horizontal line through pixel centres covers its row fully and nothing above', () => {
    expect(segmentCoverage(-5, 0, 5, 0, 1, 0, 0)).toBe(1);
    expect(segmentCoverage(-5, 0, 5, 0, 1, 2, 1)).toBe(0);
  });

  it('half way between two rows it covers half of each', () => {
    expect(segmentCoverage(-5, 0.5, 5, 0.5, 1, 0, 0)).toBeCloseTo(0.5, 15);
    expect(segmentCoverage(-5, 0.5, 5, 0.5, 1, 0, 1)).toBeCloseTo(0.5, 15);
  });

  it('the diagonal y = x: 1 − (1 − √2/2)² of the pixel on it, (√2/2)²/2 = ¼ of its neighbour', () => {
    expect(segmentCoverage(-5, -5, 5, 5, 1, 0, 0)).toBeCloseTo(1 - (1 - Math.SQRT1_2) ** 2, 14);
    expect(segmentCoverage(-5, -5, 5, 5, 1, 1, 0)).toBeCloseTo(0.25, 14);
  });

  it('butt ends: a segment ending at the pixel centre covers half of it', () => {
    expect(segmentCoverage(-5, 0, 0, 0, 1, 0, 0)).toBeCloseTo(0.5, 15);
    expect(segmentCoverage(0, 0, 0, 0, 1, 0, 0)).toBe(0);
  });

  it('the coverages of all pixels add up to the stroke’s area, length × width', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -6, max: 6, noNaN: true }),
        fc.double({ min: -6, max: 6, noNaN: true }),
        fc.double({ min: -6, max: 6, noNaN: true }),
        fc.double({ min: -6, max: 6, noNaN: true }),
        fc.double({ min: 0.1, max: 2, noNaN: true }),
        (x0, y0, x1, y1, width) => {
          let sum = 0;
          for (let i = -9; i <= 9; i++)
            for (let j = -9; j <= 9; j++) sum += segmentCoverage(x0, y0, x1, y1, width, i, j);
          expect(sum).toBeCloseTo(Math.hypot(x1 - x0, y1 - y0) * width, 9);
        },
      ),
      { numRuns: 100 },
    );
  });
});
