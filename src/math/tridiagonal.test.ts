import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { solveCyclicTridiagonal } from './cyclicTridiagonal';
import { solveTridiagonal, traceTridiagonal } from './tridiagonal';

/** A diagonally dominant system of n rows, so the Thomas algorithm is stable. */
function dominantSystem(minimum: number) {
  return fc.integer({ min: minimum, max: 40 }).chain((n) => {
    const values = fc.array(fc.double({ min: -10, max: 10, noNaN: true }), {
      minLength: n,
      maxLength: n,
    });
    return fc.tuple(values, values, values, values).map(([sub, sup, extra, rhs]) => ({
      sub,
      sup,
      diag: extra.map((e, i) => Math.abs(sub[i]) + Math.abs(sup[i]) + 1 + Math.abs(e)),
      rhs,
    }));
  });
}

function residual(
  sub: number[],
  diag: number[],
  sup: number[],
  rhs: number[],
  x: number[],
  cyclic: boolean,
): number {
  const n = diag.length;
  let worst = 0;
  for (let i = 0; i < n; i++) {
    let row = diag[i] * x[i];
    if (i > 0) row += sub[i] * x[i - 1];
    else if (cyclic) row += sub[0] * x[n - 1];
    if (i < n - 1) row += sup[i] * x[i + 1];
    else if (cyclic) row += sup[n - 1] * x[0];
    worst = Math.max(worst, Math.abs(row - rhs[i]));
  }
  return worst;
}

describe('solveTridiagonal', () => {
  it('solves the natural system for ys = [0, 1, 0, 1] exactly as by hand', () => {
    // [2 1 0 0 | 3], [1 4 1 0 | 0], [0 1 4 1 | 0], [0 0 1 2 | 3] → D = [5/3, −1/3, −1/3, 5/3]
    const x = solveTridiagonal([0, 1, 1, 1], [2, 4, 4, 2], [1, 1, 1, 0], [3, 0, 0, 3]);
    [5 / 3, -1 / 3, -1 / 3, 5 / 3].forEach((value, i) => expect(x[i]).toBeCloseTo(value, 14));
  });

  it('solves a single row', () => {
    expect(solveTridiagonal([7], [4], [9], [2])).toEqual([0.5]);
  });

  it('satisfies every equation of a diagonally dominant system', () => {
    fc.assert(
      fc.property(dominantSystem(1), ({ sub, diag, sup, rhs }) => {
        const x = solveTridiagonal(sub, diag, sup, rhs);
        expect(residual(sub, diag, sup, rhs, x, false)).toBeLessThan(1e-9);
      }),
    );
  });

  it('accepts typed arrays and leaves its input alone', () => {
    const rhs = Float64Array.of(3, 0, 0, 3);
    const x = solveTridiagonal(
      Float64Array.of(0, 1, 1, 1),
      Float64Array.of(2, 4, 4, 2),
      Float64Array.of(1, 1, 1, 0),
      rhs,
    );
    expect(x[0]).toBeCloseTo(5 / 3, 14);
    expect(Array.from(rhs)).toEqual([3, 0, 0, 3]);
  });

  it('rejects mismatched lengths, non-finite values and zero pivots', () => {
    expect(() => solveTridiagonal([0, 1], [2, 2, 2], [1, 1, 0], [1, 1, 1])).toThrow(
      /sub has 2 entries but diag has 3/,
    );
    expect(() => solveTridiagonal([0], [NaN], [0], [1])).toThrow(/diag\[0\] is NaN/);
    expect(() => solveTridiagonal([0, 1], [1, 1], [1, 0], [1, Infinity])).toThrow(/rhs\[1\]/);
    expect(() => solveTridiagonal([], [], [], [])).toThrow(/at least 1 value/);
    expect(() => solveTridiagonal([0, 1], [0, 1], [1, 0], [1, 1])).toThrow(
      /pivot of row 0 is zero/,
    );
    expect(() => solveTridiagonal([0, 1], [1, 1], [1, 0], [1, 1])).toThrow(
      /pivot of row 1 is zero/,
    );
  });
});

describe('traceTridiagonal', () => {
  it('reports the lecture’s γ and Γ for ys = [0, 1, 0]', () => {
    // Rows [2 1 | 3], [1 4 1 | 0], [1 2 | −3]:
    // γ0 = 1/2, Γ0 = 3/2; pivot 4 − 1/2 = 7/2, γ1 = 2/7, Γ1 = (0 − 3/2)/(7/2) = −3/7;
    // pivot 2 − 2/7 = 12/7, Γ2 = (−3 + 3/7)/(12/7) = −3/2.
    // Back: D2 = −3/2, D1 = −3/7 − (2/7)(−3/2) = 0, D0 = 3/2 − (1/2)·0 = 3/2.
    const trace = traceTridiagonal([0, 1, 1], [2, 4, 2], [1, 1, 0], [3, 0, -3]);
    [1 / 2, 2 / 7, 0].forEach((value, i) => expect(trace.gamma[i]).toBeCloseTo(value, 15));
    [3 / 2, -3 / 7, -3 / 2].forEach((value, i) => expect(trace.Gamma[i]).toBeCloseTo(value, 15));
    expect(trace.backSubstitution).toEqual([-1.5, 0, 1.5]);
    expect(trace.solution).toEqual([1.5, 0, -1.5]);
  });

  it('reports γ = [1/2, 2/7, 7/26, 0] and Γ = [3/2, −3/7, 3/26, 5/3] for ys = [0, 1, 0, 1]', () => {
    const trace = traceTridiagonal([0, 1, 1, 1], [2, 4, 4, 2], [1, 1, 1, 0], [3, 0, 0, 3]);
    [1 / 2, 2 / 7, 7 / 26, 0].forEach((value, i) => expect(trace.gamma[i]).toBeCloseTo(value, 15));
    [3 / 2, -3 / 7, 3 / 26, 5 / 3].forEach((value, i) =>
      expect(trace.Gamma[i]).toBeCloseTo(value, 15),
    );
    // Back substitution finds D3 = 5/3, D2 = −1/3, D1 = −1/3, D0 = 5/3, in that order.
    [5 / 3, -1 / 3, -1 / 3, 5 / 3].forEach((value, k) =>
      expect(trace.backSubstitution[k]).toBeCloseTo(value, 15),
    );
  });

  it('gives the same solution as solveTridiagonal, and Γ(n−1) = x(n−1)', () => {
    fc.assert(
      fc.property(dominantSystem(1), ({ sub, diag, sup, rhs }) => {
        const trace = traceTridiagonal(sub, diag, sup, rhs);
        const n = diag.length;
        expect(trace.solution).toEqual(solveTridiagonal(sub, diag, sup, rhs));
        expect(trace.backSubstitution[0]).toBe(trace.Gamma[n - 1]);
        expect(trace.backSubstitution.slice().reverse()).toEqual(trace.solution);
        // Each normalised row [1 γi | Γi] holds: x_i + γi x(i+1) = Γi.
        for (let i = 0; i < n - 1; i++) {
          const row = trace.solution[i] + trace.gamma[i] * trace.solution[i + 1];
          expect(Math.abs(row - trace.Gamma[i])).toBeLessThan(
            1e-9 * Math.max(1, Math.abs(trace.Gamma[i])),
          );
        }
      }),
    );
  });
});

describe('solveCyclicTridiagonal', () => {
  it('solves the closed spline system for ys = [0, 1, 0, 2]', () => {
    // Every row D(i−1) + 4Di + D(i+1) = 3(y(i+1) − y(i−1)), rhs [−3, 0, 3, 0];
    // by the symmetry D1 = D3 = 0 and 4D0 = −3: D = [−3/4, 0, 3/4, 0].
    const x = solveCyclicTridiagonal([1, 1, 1, 1], [4, 4, 4, 4], [1, 1, 1, 1], [-3, 0, 3, 0]);
    [-0.75, 0, 0.75, 0].forEach((value, i) => expect(x[i]).toBeCloseTo(value, 14));
  });

  it('satisfies every cyclic equation, corners included', () => {
    fc.assert(
      fc.property(dominantSystem(3), ({ sub, diag, sup, rhs }) => {
        const x = solveCyclicTridiagonal(sub, diag, sup, rhs);
        expect(residual(sub, diag, sup, rhs, x, true)).toBeLessThan(1e-9);
      }),
    );
  });

  it('needs three rows', () => {
    expect(() => solveCyclicTridiagonal([1, 1], [4, 4], [1, 1], [0, 0])).toThrow(
      /at least 3 values/,
    );
  });
});
