import { describe, expect, it } from 'vitest';
import { robustCap } from './measure';

// Values are drawn up to 1.25 times the cap; worked by hand from the percentile.
describe('robustCap: how far up a plot of κ or τ is drawn', () => {
  // 95 values of 0.5 and five from 1.0: the 90th percentile (index 89 of 100) is 0.5.
  const typical = (tail: number[]) => [...Array<number>(95).fill(0.5), ...tail];

  it('draws a finite peak whole: 1.9 is within four times 0.5', () => {
    const cap = robustCap(typical([1.0, 1.2, 1.5, 1.7, 1.9]));
    expect(cap).toBeCloseTo(1.9 / 1.25, 12);
    expect(1.25 * cap).toBeGreaterThanOrEqual(1.9);
  });

  it('cuts a spike far beyond the rest (a cusp): the cap stays twice 0.5', () => {
    expect(robustCap(typical([1.0, 1.2, 1.5, 1.7, 50]))).toBe(1);
  });

  it('keeps twice the percentile when that is larger, and ignores undefined values', () => {
    expect(robustCap([...typical([0.6, 0.6, 0.6, 0.6, 0.6]), null, null])).toBe(1);
    expect(robustCap([null])).toBe(1e-9);
  });
});
