import { smallNumber, sub, words } from '../../kit/format';
import {
  type Point,
  type SplineEquation,
  controlPointName,
  cubicSplineC2System,
  quadraticSplineC1,
  solveDense,
} from '../../math';
import { midpoint } from './state';

// What computeSplineC1 and computeSplineC2 should print for given points, the
// name of each row, and when two rows agree.

export type SplineKind = 'C1' | 'C2';
/** Control points that agree this closely agree. */
export const TOLERANCE = 1e-6;

/** The C² system's solution, or null where a (mistaken) system is singular. */
export function solve(equations: readonly SplineEquation[]): Point[] | null {
  try {
    const x = solveDense(
      equations.map((e) => e.coefficients),
      equations.map((e) => e.right),
    );
    return x.every((q) => q.every(Number.isFinite)) ? x : null;
  } catch {
    return null;
  }
}

/** The rows computeSplineC1 (2n + 1) or computeSplineC2 (3n + 1) should print for these points. */
export function expectedOutput(points: readonly Point[], kind: SplineKind): Point[] {
  if (kind === 'C1') {
    // The maths module's spline, the lesson's one source of truth.
    const pieces = quadraticSplineC1(points, midpoint(points[0], points[1]));
    return [points[0], ...pieces.flatMap((s) => s.slice(1))];
  }
  return solve(cubicSplineC2System(points)) ?? [];
}

/** The name of row j: pᵢ and bᵢ in turn for C¹; A … J (four points) or cⱼ for C². */
export function rowName(j: number, kind: SplineKind, n: number): string {
  if (kind === 'C1') return j % 2 === 0 ? `p${sub(j / 2)}` : `b${sub((j - 1) / 2)}`;
  const name = controlPointName(j, 3 * n + 1);
  return name.length === 1 ? name : `c${sub(j)}`;
}

export const within = (got: number, expected: number, slack: number) =>
  Math.abs(got - expected) <= Math.max(TOLERANCE, slack * (1 + 1e-9));

/** Every coordinate within 1e-6 or the printing of that number (slack 0: within 1e-6). */
export function agree(got: readonly Point[], expected: readonly Point[], slack?: readonly Point[]) {
  return (
    got.length === expected.length &&
    got.every((q, j) => q.every((v, d) => within(v, expected[j][d], slack?.[j][d] ?? 0)))
  );
}

/** A small amount as a reader writes it: 0.25, 3.2 × 10⁻⁶. */
export const amount = (v: number) =>
  Number.isNaN(v) ? 'not a number' : v !== 0 && Math.abs(v) < 1e-3 ? smallNumber(v) : words(v);
