import { trimmed } from '../../kit/format';
import { lagrangePoint, parabolaThrough, type Point } from '../../math';

// Step 0: the parabola y = a2x² + a1x + a0 through the three points, or why
// there is none that makes sense.

/** A coordinate as a person would write it: up to three decimals. */
const fmtNumber = (v: number) => trimmed(v, 3);

/** The non-parametric parabola y(x), or why there is none that makes sense. */
export type Parabola =
  | { kind: 'ok'; coefficients: [number, number, number] }
  /** It exists, but visits the points in the order P0, P2, P1 (or P1, P0, P2). */
  | { kind: 'backwards'; coefficients: [number, number, number] }
  /** Two (or three) points share an x: no function y(x) passes through them. */
  | { kind: 'same-x'; first: number; second: number; x: number };

/** Everything the figure and the panel show of y(x). */
export interface Explicit {
  parabola: Parabola;
  /** y(x) sampled from a little left of the points to a little right of them; empty for same-x. */
  curve: Point[];
  /** Where "y(x)" is written on the curve. */
  labelAt: Point | null;
  /** The apex, when it lies between the outer points in x: "fit view" shows it. */
  apex: Point | null;
  /** Two points above one another: the vertical line from the first to the last of them. */
  column: [Point, Point] | null;
  /** On the figure: why there is no parabola, or why it is dashed. Null when all is well. */
  figureNote: string | null;
  /** In the panel: the same, said beside the system of equations. */
  panelWarning: string | null;
}

export function explicitParabola(p: readonly Point[]): Parabola {
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

/**
 * Which points share an x, in words: "P0 and P1 share x = 2", "all three
 * points share x = 2", or "all three points are at one spot, (1, 1)".
 */
export function sameXWords(p: readonly Point[], x: number): string {
  const sharing = [0, 1, 2].filter((i) => p[i][0] === x);
  if (sharing.length === 3) {
    if (p.every((q) => q[1] === p[0][1])) {
      return `all three points are at one spot, (${fmtNumber(x)}, ${fmtNumber(p[0][1])})`;
    }
    return `all three points share x = ${fmtNumber(x)}`;
  }
  return `P${sharing[0]} and P${sharing[1]} share x = ${fmtNumber(x)}`;
}

/** Points (x, y(x)) of the parabola through p, from x = from to x = to. */
function sampleParabola(p: readonly Point[], from: number, to: number, count: number): Point[] {
  const xs = p.map((q) => q[0]);
  const ys = p.map((q) => [q[1]]);
  return Array.from({ length: count + 1 }, (_, k) => {
    const x = from + ((to - from) * k) / count;
    return [x, lagrangePoint(xs, ys, x)[0]];
  });
}

export function deriveExplicit(p: readonly Point[]): Explicit {
  const parabola = explicitParabola(p);
  if (parabola.kind === 'same-x') {
    const words = sameXWords(p, parabola.x);
    const column = p.filter((q) => q[0] === parabola.x);
    return {
      parabola,
      curve: [],
      labelAt: null,
      apex: null,
      column: [column[0], column[column.length - 1]],
      figureNote: `No parabola y(x): ${words}, and a function has one y at each x.`,
      panelWarning: `There is none: ${words}, so the system below has equal rows and no solution.`,
    };
  }
  const xs = p.map((q) => q[0]);
  const [low, high] = [Math.min(...xs), Math.max(...xs)];
  const span = high - low;
  const curve = sampleParabola(p, low - 0.15 * span, high + 0.15 * span, 120);
  const [a0, a1, a2] = parabola.coefficients;
  // y′ = 2a2x + a1 = 0; a2 = 0 (three points on a line) has no apex.
  const apexX = a2 === 0 ? NaN : -a1 / (2 * a2);
  const apex: Point | null =
    apexX > low && apexX < high ? [apexX, a0 + a1 * apexX + a2 * apexX * apexX] : null;
  const [x0, x1, x2] = xs.map(fmtNumber);
  const backwards = parabola.kind === 'backwards';
  return {
    parabola,
    curve,
    labelAt: curve[Math.round(curve.length * 0.8)],
    apex,
    column: null,
    figureNote: backwards
      ? `Backwards in x: x1 = ${x1} is not between ${x0} and ${x2}. The dashed y(x) meets all three points, but not in order: a function cannot turn back.`
      : null,
    panelWarning: backwards
      ? `It exists, but it meets the points in the wrong order: x1 = ${x1} is not between x0 = ${x0} and x2 = ${x2}. A function y(x) cannot go back in x.`
      : null,
  };
}
