import { describe, expect, it } from 'vitest';
import { basisRows } from './basisSamples';

describe('the sampled basis rows', () => {
  it('each N_{i,r} keeps only its support [u_i, u_{i+r+1}] and a zero either side', () => {
    const knots = Array.from({ length: 11 }, (_, j) => j);
    const rows = basisRows(knots, 3);
    // Uniform cubic N_{2,3} lives on [2, 6]; at its middle u = 4 it is 2/3, at u = 3 and 5 it is 1/6.
    const samples = rows[3][2];
    expect(samples[0]).toBeLessThan(2);
    expect(samples[1]).toBe(0);
    expect(samples[samples.length - 2]).toBe(6);
    expect(samples[samples.length - 1]).toBe(0);
    const at = (u: number) => {
      for (let k = 0; k < samples.length; k += 2) if (samples[k] === u) return samples[k + 1];
      return NaN;
    };
    expect(at(4)).toBeCloseTo(2 / 3, 14);
    expect(at(3)).toBeCloseTo(1 / 6, 14);
    expect(at(5)).toBeCloseTo(1 / 6, 14);
    // Row 0 is a step: 0 just left of u_i, 1 from u_i, 0 again at u_{i+1}.
    const step = rows[0][4];
    expect([...step.filter((_, k) => k % 2 === 1)]).toEqual([
      0,
      ...Array<number>((step.length >> 1) - 2).fill(1),
      0,
    ]);
    expect(step[2]).toBe(4);
    expect(step[step.length - 2]).toBe(5);
  });
});

describe('the ends of the knot range, in floating point', () => {
  it('samples up to the last knot, not a rounding past it (u₀ + width can be 13.781000000000002)', () => {
    // −2.979 + (13.781 − (−2.979)) = 13.781000000000002 in doubles: worked in node.
    const knots = [-2.979, -2.979, -2.979, -2.979, 5, 13.781, 13.781, 13.781, 13.781];
    const rows = basisRows(knots, 3);
    const us = rows[0][0].filter((_, k) => k % 2 === 0);
    expect(Math.max(...us)).toBeLessThanOrEqual(13.781);
  });
});
