import {
  type Point,
  type TridiagonalSystem,
  type TridiagonalTrace,
  clampedCubicSystem,
  cubicSplineSegments,
  naturalCubicSystem,
  traceTridiagonal,
} from '../../math';
import { type RoadInputs, hasSolve } from './state';

/**
 * The spline's system for both coordinates: one matrix (it depends only on the
 * number of villages and the end conditions) and two right-hand sides, each
 * solved by the Thomas algorithm with every γi, Γi and Di recorded.
 */
export interface RoadSolve {
  /** The matrix: a_i, b_i, c_i of row i (sub[0] and sup[n−1] are outside it). */
  matrix: TridiagonalSystem;
  /** Right-hand sides for x and for y. */
  rhs: [number[], number[]];
  /** The Thomas algorithm on x and on y. */
  trace: [TridiagonalTrace, TridiagonalTrace];
  /** Rows (= villages, m + 1). */
  n: number;
}

export function buildSolve(state: RoadInputs): RoadSolve | null {
  if (!hasSolve(state)) return null;
  const xs = state.villages.map((p) => p[0]);
  const ys = state.villages.map((p) => p[1]);
  const systems =
    state.road === 'clamped'
      ? [
          clampedCubicSystem(xs, state.startGradient[0], state.endGradient[0]),
          clampedCubicSystem(ys, state.startGradient[1], state.endGradient[1]),
        ]
      : [naturalCubicSystem(xs), naturalCubicSystem(ys)];
  const trace = systems.map((s) => traceTridiagonal(s.sub, s.diag, s.sup, s.rhs)) as [
    TridiagonalTrace,
    TridiagonalTrace,
  ];
  return {
    matrix: systems[0],
    rhs: [systems[0].rhs.slice(), systems[1].rhs.slice()],
    trace,
    n: xs.length,
  };
}

/** Where the solve stands: rows swept so far, and gradients fixed by back substitution. */
export interface SolveProgress {
  /** Rows 0 … swept−1 have become [1 γi | Γi]. */
  swept: number;
  /** D(n−1), D(n−2), …, D(n−fixed) are known. */
  fixed: number;
  /** The row the solve worked on last, or null before it starts. */
  row: number | null;
}

/** The solve of n rows with `swept` rows swept and then `fixed` gradients fixed. */
export function solveProgress(n: number, swept: number, fixed: number): SolveProgress {
  const row = fixed > 0 ? n - fixed : swept > 0 ? swept - 1 : null;
  return { swept, fixed, row };
}

/** Is D_i known at this point of the solve? */
export const isFixed = (n: number, progress: SolveProgress, i: number) => i >= n - progress.fixed;

/** The gradients D0 … Dm the solve found, as vectors (x from one trace, y from the other). */
export const solvedGradients = (solve: RoadSolve): Point[] =>
  solve.trace[0].solution.map((dx, i) => [dx, solve.trace[1].solution[i]]);

/** The pieces of road whose two end gradients are known: segments n−fixed … n−2. */
export function builtPieces(
  villages: readonly Point[],
  gradients: readonly Point[],
  progress: SolveProgress,
): Point[][] {
  if (progress.fixed < 2) return [];
  const from = villages.length - progress.fixed;
  return cubicSplineSegments(villages.slice(from), gradients.slice(from));
}
