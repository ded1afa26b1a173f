import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { basisValuesAt, sampleBasis } from './basisSamples';

// The linear Bernstein pair 1 − μ, μ, and the Hermite basis of the lecture:
// H0 = (1−μ)²(1+2μ), H1 = μ²(3−2μ), H2 = μ(1−μ)², H3 = −μ²(1−μ).
const linear = (mu: number) => [1 - mu, mu];
const hermite = (mu: number) => [
  (1 - mu) ** 2 * (1 + 2 * mu),
  mu ** 2 * (3 - 2 * mu),
  mu * (1 - mu) ** 2,
  -(mu ** 2) * (1 - mu),
];

describe('sampleBasis', () => {
  it('lays each function out as interleaved μ, value at μ = k / count', () => {
    const { curves, count } = sampleBasis(linear, 4);
    expect(count).toBe(4);
    expect([...curves[0]]).toEqual([0, 1, 0.25, 0.75, 0.5, 0.5, 0.75, 0.25, 1, 0]);
    expect([...curves[1]]).toEqual([0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1]);
  });

  it('finds the lowest and highest values, the first function and μ winning a tie', () => {
    const { lowest, highest } = sampleBasis(linear, 4);
    // Both functions reach 0 and 1; function 0 is searched first.
    expect(lowest).toEqual({ value: 0, mu: 1, index: 0 });
    expect(highest).toEqual({ value: 1, mu: 0, index: 0 });
  });

  it('finds H3 at its lowest, −4/27 at μ = 2/3 (H3′ = −2μ + 3μ² = 0)', () => {
    const { lowest } = sampleBasis(hermite, 3);
    expect(lowest.index).toBe(3);
    expect(lowest.mu).toBeCloseTo(2 / 3, 15);
    expect(lowest.value).toBeCloseTo(-4 / 27, 15);
  });

  it('refuses a count below 1 and values that are not numbers', () => {
    expect(() => sampleBasis(linear, 0)).toThrow(RangeError);
    expect(() => sampleBasis(() => [Number.NaN], 2)).toThrow(/sampleBasis/);
  });
});

describe('basisValuesAt', () => {
  it('is exact at the samples and for straight lines', () => {
    const samples = sampleBasis(linear, 4);
    expect(basisValuesAt(samples, 0.5)).toEqual([0.5, 0.5]);
    fc.assert(
      fc.property(fc.double({ min: 0, max: 1, noNaN: true }), (mu) => {
        const [a, b] = basisValuesAt(samples, mu);
        expect(a).toBeCloseTo(1 - mu, 12);
        expect(b).toBeCloseTo(mu, 12);
      }),
    );
  });

  it('interpolates between samples: μ² from 0, 0.25, 1 reads 0.125 at μ = 1/4', () => {
    expect(
      basisValuesAt(
        sampleBasis((mu) => [mu * mu], 2),
        0.25,
      ),
    ).toEqual([0.125]);
  });

  it('clamps μ to [0, 1]', () => {
    const samples = sampleBasis(hermite, 10);
    const plain = (values: number[]) => values.map((v) => v + 0); // −0 reads as 0
    expect(plain(basisValuesAt(samples, -3))).toEqual([1, 0, 0, 0]);
    expect(plain(basisValuesAt(samples, 7))).toEqual([0, 1, 0, 0]);
  });
});
