import { checkNumbers } from './validate';

// The Thomas algorithm (lecture notes, "solving the tridiagonal system"):
// Gaussian elimination specialised to a tridiagonal matrix, O(n). Row i reads
// a_i x(i−1) + b_i x_i + c_i x(i+1) = d_i. The forward sweep normalises each
// row to [1 γi | Γi]:
//   γ0 = c0 / b0,  Γ0 = d0 / b0,
//   γi = ci / (bi − ai γ(i−1)),  Γi = (di − ai Γ(i−1)) / (bi − ai γ(i−1)),
// and back substitution gives x(n−1) = Γ(n−1), xi = Γi − γi x(i+1).

/** A tridiagonal system: `sub[i]`, `diag[i]`, `sup[i]` are a_i, b_i, c_i of row i, `rhs[i]` is d_i. */
export interface TridiagonalSystem {
  /** a_i, the coefficient of x(i−1) in row i; `sub[0]` is outside the matrix (ignored). */
  readonly sub: readonly number[];
  /** b_i, the diagonal. */
  readonly diag: readonly number[];
  /** c_i, the coefficient of x(i+1) in row i; `sup[n−1]` is outside the matrix (ignored). */
  readonly sup: readonly number[];
  /** d_i, the right-hand side. */
  readonly rhs: readonly number[];
}

/** Every intermediate value of the Thomas algorithm, for a step-by-step lesson. */
export interface TridiagonalTrace {
  /** The lecture's γi of the forward sweep, row by row (γ(n−1) = 0: the last row has no c). */
  readonly gamma: number[];
  /** The lecture's Γi of the forward sweep, row by row: row i becomes [1 γi | Γi]. */
  readonly Gamma: number[];
  /** The unknowns in the order back substitution finds them: x(n−1), x(n−2), …, x0. */
  readonly backSubstitution: number[];
  /** The solution x0 … x(n−1) in index order. */
  readonly solution: number[];
}

/**
 * Solves the tridiagonal system by the Thomas algorithm in O(n): forward sweep,
 * then back substitution. `sub[0]` and `sup[n−1]` are ignored. RangeError when
 * the lengths differ, a value is not finite, or a pivot `bi − ai γ(i−1)` is zero
 * (the algorithm needs, e.g., a diagonally dominant matrix).
 */
export function solveTridiagonal(
  sub: ArrayLike<number>,
  diag: ArrayLike<number>,
  sup: ArrayLike<number>,
  rhs: ArrayLike<number>,
): number[] {
  checkSystem('solveTridiagonal', sub, diag, sup, rhs);
  const n = diag.length;
  const solution = new Array<number>(n);
  thomas('solveTridiagonal', sub, diag, sup, rhs, new Float64Array(n), solution);
  return solution;
}

/**
 * The Thomas algorithm with every intermediate value recorded: the γi and Γi of
 * the forward sweep and each unknown of the back substitution, last first.
 * Same checks and same numbers as `solveTridiagonal`.
 */
export function traceTridiagonal(
  sub: ArrayLike<number>,
  diag: ArrayLike<number>,
  sup: ArrayLike<number>,
  rhs: ArrayLike<number>,
): TridiagonalTrace {
  checkSystem('traceTridiagonal', sub, diag, sup, rhs);
  const n = diag.length;
  const gamma = new Array<number>(n);
  const Gamma = new Array<number>(n);
  forwardSweep('traceTridiagonal', sub, diag, sup, rhs, gamma, Gamma);
  const solution = Gamma.slice();
  backSubstitute('traceTridiagonal', gamma, solution, n);
  const backSubstitution = new Array<number>(n);
  for (let k = 0; k < n; k++) backSubstitution[k] = solution[n - 1 - k];
  return { gamma, Gamma, backSubstitution, solution };
}

/**
 * The Thomas algorithm without argument checks (other than pivots), writing γ
 * into `gamma` and the solution into `out` (which may be `rhs` itself).
 * Internal building block for the spline solvers.
 */
export function thomas(
  caller: string,
  sub: ArrayLike<number>,
  diag: ArrayLike<number>,
  sup: ArrayLike<number>,
  rhs: ArrayLike<number>,
  gamma: { [index: number]: number },
  out: { [index: number]: number },
): void {
  forwardSweep(caller, sub, diag, sup, rhs, gamma, out);
  backSubstitute(caller, gamma, out, diag.length);
}

/** The forward sweep: writes γi into `gamma` and Γi into `Gamma`. */
function forwardSweep(
  caller: string,
  sub: ArrayLike<number>,
  diag: ArrayLike<number>,
  sup: ArrayLike<number>,
  rhs: ArrayLike<number>,
  gamma: { [index: number]: number },
  Gamma: { [index: number]: number },
): void {
  const n = diag.length;
  let pivot = diag[0];
  if (pivot === 0) throw zeroPivot(caller, 0);
  gamma[0] = n > 1 ? sup[0] / pivot : 0;
  let previous = rhs[0] / pivot;
  Gamma[0] = previous;
  for (let i = 1; i < n; i++) {
    pivot = diag[i] - sub[i] * gamma[i - 1];
    if (pivot === 0) throw zeroPivot(caller, i);
    gamma[i] = i < n - 1 ? sup[i] / pivot : 0;
    previous = (rhs[i] - sub[i] * previous) / pivot;
    Gamma[i] = previous;
  }
}

/** Back substitution in place: `x` holds Γ on entry and the solution on exit. */
function backSubstitute(
  caller: string,
  gamma: { [index: number]: number },
  x: { [index: number]: number },
  n: number,
): void {
  for (let i = n - 2; i >= 0; i--) x[i] -= gamma[i] * x[i + 1];
  for (let i = 0; i < n; i++) {
    if (!Number.isFinite(x[i])) {
      throw new RangeError(
        `${caller}: the solution overflowed at x${i}; the matrix is too close to singular for the Thomas algorithm.`,
      );
    }
  }
}

function zeroPivot(caller: string, row: number): RangeError {
  return new RangeError(
    `${caller}: the pivot of row ${row} is zero, so the Thomas algorithm cannot divide by it; use a diagonally dominant matrix (|b_i| > |a_i| + |c_i|).`,
  );
}

/** Checks four equal-length arrays of finite numbers, at least one row. */
export function checkSystem(
  caller: string,
  sub: ArrayLike<number>,
  diag: ArrayLike<number>,
  sup: ArrayLike<number>,
  rhs: ArrayLike<number>,
  minimum = 1,
): void {
  checkNumbers(caller, 'diag', diag, minimum);
  const n = diag.length;
  for (const [name, values] of [
    ['sub', sub],
    ['sup', sup],
    ['rhs', rhs],
  ] as const) {
    checkNumbers(caller, name, values, 0);
    if (values.length !== n) {
      throw new RangeError(
        `${caller}: ${name} has ${values.length} entries but diag has ${n}; every row needs one of each.`,
      );
    }
  }
}
