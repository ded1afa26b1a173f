import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bsplineBasis } from '../../math';
import { equalSpacing, pieceAt, pieceTex, polynomialTex, uniformPieces } from './uniformPieces';

describe('the uniform B-spline pieces, by Cox–de Boor on equal knots', () => {
  it('row 3 is the continuation notes’ B0 … B3: (1−t)³/6, (3t³−6t²+4)/6, (−3t³+3t²+3t+1)/6, t³/6', () => {
    const pieces = uniformPieces(3);
    // Coefficients of 1, t, t², t³ times 6: the rows of the notes' matrix
    // 1/6 [1 −3 3 −1; 4 0 −6 3; 1 3 3 −3; 0 0 0 1].
    expect(pieces.map((p) => p.coefficients)).toEqual([
      [1, -3, 3, -1],
      [4, 0, -6, 3],
      [1, 3, 3, -3],
      [0, 0, 0, 1],
    ]);
    expect(pieces.every((p) => p.denominator === 6)).toBe(true);
    expect(pieces.map(pieceTex)).toEqual([
      '\\tfrac{1}{6}(1 - t)^{3}',
      '\\tfrac{1}{6}(3t^{3} - 6t^{2} + 4)',
      '\\tfrac{1}{6}(-3t^{3} + 3t^{2} + 3t + 1)',
      '\\tfrac{1}{6}t^{3}',
    ]);
  });

  it('rows 0, 1 and 2: 1; 1 − t and t; (1−t)²/2, (−2t²+2t+1)/2, t²/2', () => {
    expect(uniformPieces(0).map(pieceTex)).toEqual(['1']);
    expect(uniformPieces(1).map(pieceTex)).toEqual(['1 - t', 't']);
    expect(uniformPieces(2).map(pieceTex)).toEqual([
      '\\tfrac{1}{2}(1 - t)^{2}',
      '\\tfrac{1}{2}(-2t^{2} + 2t + 1)',
      '\\tfrac{1}{2}t^{2}',
    ]);
    expect(polynomialTex([0, 0, -1])).toBe('-t^{2}');
  });

  it('each piece is the B-spline basis function on the knots 0, 1, 2, … (degrees 0 … 5), and they sum to 1', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 0, max: 5 }),
        fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true }),
        (r, t) => {
          const knots = Array.from({ length: 2 * r + 2 }, (_, j) => j);
          const pieces = uniformPieces(r);
          // The span [r, r + 1): piece k is N_{k, r}.
          const sum = pieces.reduce((a, p) => a + pieceAt(p, t), 0);
          return (
            Math.abs(sum - 1) < 1e-12 &&
            pieces.every(
              (p, k) => Math.abs(pieceAt(p, t) - bsplineBasis(knots, r, k, r + t)) < 1e-12,
            )
          );
        },
      ),
    );
  });

  it('finds equal spacing only where every knot of the run is evenly spaced', () => {
    expect(equalSpacing([0, 1, 2, 3, 4], 0, 4)).toBe(1);
    expect(equalSpacing([0, 0.25, 0.5, 0.75], 0, 3)).toBe(0.25);
    expect(equalSpacing([0, 0, 0, 0, 0.25, 0.5], 0, 5)).toBeNull();
    expect(equalSpacing([0, 1, 2, 4], 0, 3)).toBeNull();
    expect(equalSpacing([0, 1, 2], -1, 2)).toBeNull();
  });
});
