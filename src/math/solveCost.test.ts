import { describe, expect, it } from 'vitest';
import {
  constraintCount,
  gaussianEliminationOperationCount,
  thomasOperationCount,
} from './solveCost';

/** Counts the operations of the Thomas algorithm by running it on counting numbers. */
function countThomas(n: number, r: number): number {
  let ops = 0;
  const gamma: number[] = [];
  const op = (v: number) => (ops++, v);
  const Gamma: number[][] = Array.from({ length: r }, () => []);
  let pivot = 2;
  if (n > 1) gamma[0] = op(1 / pivot);
  for (let k = 0; k < r; k++) Gamma[k][0] = op(1 / pivot);
  for (let i = 1; i < n; i++) {
    pivot = op(4 - op(gamma[i - 1]));
    if (i < n - 1) gamma[i] = op(1 / pivot);
    for (let k = 0; k < r; k++) Gamma[k][i] = op(op(1 - op(Gamma[k][i - 1])) / pivot);
  }
  for (let k = 0; k < r; k++) for (let i = n - 2; i >= 0; i--) op(op(gamma[i] * 1) - 1);
  return ops;
}

/** Counts the operations of dense Gaussian elimination by running its loops. */
function countGauss(N: number, r: number): number {
  let ops = 0;
  for (let k = 0; k < N - 1; k++)
    for (let i = k + 1; i < N; i++) ops += 1 + 2 * (N - k - 1) + 2 * r;
  for (let s = 0; s < r; s++) for (let i = N - 1; i >= 0; i--) ops += 2 * (N - 1 - i) + 1;
  return ops;
}

describe('operation counts', () => {
  it('match the Thomas algorithm counted step by step', () => {
    for (let n = 1; n <= 30; n++)
      for (const r of [1, 2, 3]) expect(thomasOperationCount(n, r)).toBe(countThomas(n, r));
    // Linear in n: 13n − 11 for x and y together.
    expect(thomasOperationCount(501, 2)).toBe(13 * 501 - 11);
  });

  it('match dense Gaussian elimination counted loop by loop', () => {
    for (let N = 1; N <= 25; N++)
      for (const r of [1, 2, N])
        expect(gaussianEliminationOperationCount(N, r)).toBe(countGauss(N, r));
    // Cubic in N: about 2N³/3.
    const N = 2000;
    expect(gaussianEliminationOperationCount(N) / ((2 * N ** 3) / 3)).toBeCloseTo(1, 2);
  });

  it('give the lecture’s counting argument for the natural cubic spline', () => {
    // m = 5 segments: 20 unknowns, 4(m−1) = 16 inner, 2 end positions, 2 free.
    expect(constraintCount(6, 3, 2)).toEqual({
      segments: 5,
      unknowns: 20,
      inner: 16,
      ends: 2,
      free: 2,
    });
    // Two points: one segment, no inner join.
    expect(constraintCount(2, 3, 2)).toEqual({
      segments: 1,
      unknowns: 4,
      inner: 0,
      ends: 2,
      free: 2,
    });
    // C¹ quadratics: one free condition (the gradient at P0).
    expect(constraintCount(6, 2, 1).free).toBe(1);
    // A closed C² cubic: no free conditions.
    expect(constraintCount(6, 3, 2, true)).toEqual({
      segments: 6,
      unknowns: 24,
      inner: 24,
      ends: 0,
      free: 0,
    });
  });

  it('refuse nonsense', () => {
    expect(() => thomasOperationCount(0)).toThrow(RangeError);
    expect(() => gaussianEliminationOperationCount(1.5)).toThrow(RangeError);
    expect(() => constraintCount(1, 3, 2)).toThrow(RangeError);
  });
});
