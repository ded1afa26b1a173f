import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, polygon, unitParameter } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { bezierBasisMatrix, bezierToPowerBasis, powerBasisToBezier } from './powerBasis';
import type { Point } from './vec';

function evaluatePower(coefficients: readonly Point[], u: number): Point {
  return coefficients[0].map((_, d) =>
    coefficients.reduceRight((sum, coefficient) => sum * u + coefficient[d], 0),
  );
}

describe('bezierBasisMatrix', () => {
  it('is the lecture’s cubic matrix', () => {
    expect(bezierBasisMatrix(3)).toEqual([
      [1, 0, 0, 0],
      [-3, 3, 0, 0],
      [3, -6, 3, 0],
      [-1, 3, -3, 1],
    ]);
  });

  it('covers low degrees', () => {
    expect(bezierBasisMatrix(0)).toEqual([[1]]);
    expect(bezierBasisMatrix(1)).toEqual([
      [1, 0],
      [-1, 1],
    ]);
    expect(bezierBasisMatrix(2)).toEqual([
      [1, 0, 0],
      [-2, 2, 0],
      [1, -2, 1],
    ]);
  });

  it('rejects a negative degree', () => {
    expect(() => bezierBasisMatrix(-1)).toThrow(RangeError);
  });
});

describe('power basis conversion', () => {
  it('gives the power form of the lecture cubic', () => {
    const coefficients = bezierToPowerBasis([[0], [1], [3], [4]]);
    // x(u) = 3u + 3u² − 2u³
    expect(coefficients).toEqual([[0], [3], [3], [-2]]);
  });

  it('evaluates to the same curve', () => {
    fc.assert(
      fc.property(polygon(1, 7), unitParameter, (points, u) => {
        expectClose(evaluatePower(bezierToPowerBasis(points), u), bezierPoint(points, u), 1e-7);
      }),
    );
  });

  it('round-trips Bézier → power → Bézier', () => {
    fc.assert(
      fc.property(polygon(1, 7), (points) => {
        const back = powerBasisToBezier(bezierToPowerBasis(points));
        back.forEach((p, i) => expectClose(p, points[i], 1e-8));
      }),
    );
  });
});
