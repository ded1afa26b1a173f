import type { Point2 } from '../../app/lesson';
import {
  centripetalMu,
  chordLengthMu,
  lagrangePoint,
  parabolaThrough,
  parametricQuadratic,
  parametricQuadraticPoint,
  type Point,
} from '../../math';
import { MU_MAX, MU_MIN } from './state';

// What the figure and the panel both need, computed once from src/math.

/** The non-parametric parabola y(x), or why there is none that makes sense. */
export type Parabola =
  | { kind: 'ok'; coefficients: [number, number, number] }
  /** It exists, but visits the points in the order P0, P2, P1 (or P1, P0, P2). */
  | { kind: 'backwards'; coefficients: [number, number, number] }
  /** Two (or three) points share an x: no function y(x) passes through them. */
  | { kind: 'same-x'; first: number; second: number; x: number };

/**
 * Which points share an x, in words: "P0 and P1 share x = 2", "all three
 * points share x = 2", or "all three points are at one spot, (1, 1)".
 */
export function sameXWords(p: readonly Point2[], x: number, fmt: (v: number) => string): string {
  const sharing = [0, 1, 2].filter((i) => p[i][0] === x);
  if (sharing.length === 3) {
    if (p.every((q) => q[1] === p[0][1])) {
      return `all three points are at one spot, (${fmt(x)}, ${fmt(p[0][1])})`;
    }
    return `all three points share x = ${fmt(x)}`;
  }
  return `P${sharing[0]} and P${sharing[1]} share x = ${fmt(x)}`;
}

export function explicitParabola(p: readonly Point2[]): Parabola {
  for (const [i, j] of [
    [0, 1],
    [1, 2],
    [0, 2],
  ]) {
    if (p[i][0] === p[j][0]) return { kind: 'same-x', first: i, second: j, x: p[i][0] };
  }
  const coefficients = parabolaThrough(p[0], p[1], p[2]);
  // P1 must lie between P0 and P2 in x for y(x) to pass them in order.
  const backwards = (p[1][0] - p[0][0]) * (p[2][0] - p[1][0]) < 0;
  return { kind: backwards ? 'backwards' : 'ok', coefficients };
}

/** Points (x, y(x)) of the parabola from x = from to x = to. */
export function sampleParabola(p: readonly Point2[], from: number, to: number, count = 120) {
  const xs = p.map((q) => q[0]);
  const ys = p.map((q) => [q[1]]);
  return Array.from({ length: count + 1 }, (_, k) => {
    const x = from + ((to - from) * k) / count;
    return [x, lagrangePoint(xs, ys, x)[0]] as Point;
  });
}

/** The parametric quadratic through P0 (μ = 0), P1 (μ = μ1), P2 (μ = 1), sampled. */
export function sampleQuadratic(p: readonly Point2[], mu: number, count = 96): Point[] {
  return Array.from({ length: count + 1 }, (_, k) =>
    parametricQuadraticPoint(p[0], p[1], p[2], mu, k / count),
  );
}

/** Points at μ = 0, 0.1, …, 1: equal steps of the parameter. */
export function quadraticTicks(p: readonly Point2[], mu: number): Point[] {
  return Array.from({ length: 11 }, (_, k) =>
    parametricQuadraticPoint(p[0], p[1], p[2], mu, k / 10),
  );
}

export function quadraticCoefficients(p: readonly Point2[], mu: number) {
  return parametricQuadratic(p[0], p[1], p[2], mu);
}

export interface MuRule {
  id: 'uniform' | 'chord' | 'centripetal';
  name: string;
  /** μ1 chosen by the rule; 0 or 1 when P1 coincides with an end point. */
  mu: number;
  /** The rule's μ1 lies in the slider's range, so its curve exists and can be drawn. */
  usable: boolean;
}

/** The three rules of the notes for choosing μ1 from the points. */
export function muRules(p: readonly Point2[]): MuRule[] {
  const rules: Omit<MuRule, 'usable'>[] = [
    { id: 'uniform', name: 'Uniform', mu: 0.5 },
    { id: 'chord', name: 'Chord length', mu: chordLengthMu(p[0], p[1], p[2]) },
    { id: 'centripetal', name: 'Centripetal', mu: centripetalMu(p[0], p[1], p[2]) },
  ];
  return rules.map((rule) => ({ ...rule, usable: rule.mu > 0 && rule.mu < 1 }));
}

/** μ1 kept inside the slider's range (the curve is undefined at 0 and 1). */
export const clampMu = (mu: number) => Math.min(MU_MAX, Math.max(MU_MIN, mu));
