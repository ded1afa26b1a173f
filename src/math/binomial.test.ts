import { describe, expect, it } from 'vitest';
import { binomial } from './binomial';

function exactBinomial(n: number, k: number): bigint {
  let value = 1n;
  for (let i = 1; i <= k; i++) value = (value * BigInt(n - k + i)) / BigInt(i);
  return value;
}

describe('binomial', () => {
  it('matches small values of Pascal’s triangle', () => {
    expect([0, 1, 2, 3, 4].map((k) => binomial(4, k))).toEqual([1, 4, 6, 4, 1]);
    expect(binomial(0, 0)).toBe(1);
    expect(binomial(10, 3)).toBe(120);
  });

  it('is exact up to n = 56, including C(56, 28)', () => {
    expect(binomial(56, 28)).toBe(7648690600760440);
    for (let n = 0; n <= 56; n++) {
      for (let k = 0; k <= n; k++) expect(BigInt(binomial(n, k))).toBe(exactBinomial(n, k));
    }
  });

  it('is the nearest double beyond n = 56', () => {
    expect(binomial(57, 28)).toBe(Number(exactBinomial(57, 28)));
    expect(binomial(100, 50)).toBe(Number(exactBinomial(100, 50)));
    expect(binomial(1000, 3)).toBe(166167000);
    expect(binomial(2000, 1000)).toBe(Infinity);
  });

  it('is 0 outside 0 ≤ k ≤ n', () => {
    expect(binomial(5, -1)).toBe(0);
    expect(binomial(5, 6)).toBe(0);
    expect(binomial(0, 1)).toBe(0);
  });

  it('rejects n that is negative or not whole', () => {
    expect(() => binomial(-1, 0)).toThrow(RangeError);
    expect(() => binomial(2.5, 1)).toThrow(/n is 2.5; it must be a whole number/);
    expect(() => binomial(4, 1.5)).toThrow(RangeError);
    expect(() => binomial(NaN, 1)).toThrow(RangeError);
  });
});
