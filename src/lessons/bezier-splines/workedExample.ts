import {
  type Point,
  binomial,
  bezierToPowerBasis,
  powerBasisToBezier,
  quadraticSplineC1,
  solveCubicSplineC2System,
} from '../../math';
import { midpoint } from './state';

// The practical's computeSplineC1 and computeSplineC2 worked by hand, as a
// student would on paper, with the numbers the figure shows.

/** C¹ quadratic spline: b₀ the midpoint of p₀p₁ (the practical's suggestion), then bᵢ = 2pᵢ − bᵢ₋₁. */
export interface HandC1 {
  /** b₀ … bₙ₋₁. */
  b: Point[];
  /** What computeSplineC1 returns: p₀, b₀, p₁, b₁, …, pₙ (2n + 1 rows). */
  output: Point[];
}

export function handC1(p: readonly Point[]): HandC1 {
  const pieces = quadraticSplineC1(p, midpoint(p[0], p[1]));
  return {
    b: pieces.map((piece) => piece[1]),
    output: [p[0], ...pieces.flatMap((s) => s.slice(1))],
  };
}

/**
 * A control point of the C² spline while B = c₁ is still unknown: a·B + v.
 * Every equation of the system is linear, so walking them from the start
 * keeps each control point in this form until the last equation fixes B.
 */
export interface InTermsOfB {
  a: number;
  v: Point;
}

const form = (a: number, v: Point): InTermsOfB => ({ a, v });
/** Σ kᵢ·fᵢ: a combination of control points, still in terms of B. */
const combine = (...terms: [number, InTermsOfB][]): InTermsOfB =>
  terms.reduce(
    (sum, [k, f]) => form(sum.a + k * f.a, [sum.v[0] + k * f.v[0], sum.v[1] + k * f.v[1]]),
    form(0, [0, 0]),
  );
const valueAt = (f: InTermsOfB, B: Point): Point => [f.a * B[0] + f.v[0], f.a * B[1] + f.v[1]];

/**
 * C² cubic spline by substitution, the practical's equations in the order a
 * student walks them: B unknown; the natural start gives C = 2B − A; at each
 * inner joint c₃ᵢ, C¹ gives c₃ᵢ₊₁ = 2c₃ᵢ − c₃ᵢ₋₁ and C² gives
 * c₃ᵢ₊₂ = c₃ᵢ₋₂ − 2c₃ᵢ₋₁ + 2c₃ᵢ₊₁; the natural end, the one equation left, fixes B.
 */
export interface HandC2 {
  /** Each control point c₀ … c₃ₙ in terms of B (c₁ = B itself). */
  forms: InTermsOfB[];
  /** The natural end c₃ₙ₋₂ − 2c₃ₙ₋₁ + c₃ₙ in terms of B: it must be 0. */
  end: InTermsOfB;
  B: Point;
  /** What computeSplineC2 returns: c₀ … c₃ₙ (3n + 1 rows). */
  controls: Point[];
  /** The largest difference from solving the whole system at once (solveCubicSplineC2System). */
  solverDifference: number;
}

export function handC2(p: readonly Point[]): HandC2 {
  const n = p.length - 1;
  const forms: InTermsOfB[] = new Array<InTermsOfB>(3 * n + 1);
  const given = (i: number) => form(0, p[i].slice());
  forms[0] = given(0);
  forms[1] = form(1, [0, 0]);
  // Natural start c₀ − 2c₁ + c₂ = 0.
  forms[2] = combine([2, forms[1]], [-1, forms[0]]);
  for (let i = 1; i < n; i++) {
    const k = 3 * i;
    forms[k] = given(i);
    // C¹: c₃ᵢ₋₁ − 2c₃ᵢ + c₃ᵢ₊₁ = 0.
    forms[k + 1] = combine([2, forms[k]], [-1, forms[k - 1]]);
    // C²: c₃ᵢ₋₂ − 2c₃ᵢ₋₁ + 2c₃ᵢ₊₁ − c₃ᵢ₊₂ = 0.
    forms[k + 2] = combine([1, forms[k - 2]], [-2, forms[k - 1]], [2, forms[k + 1]]);
  }
  forms[3 * n] = given(n);
  const end = combine([1, forms[3 * n - 2]], [-2, forms[3 * n - 1]], [1, forms[3 * n]]);
  // end.a·B + end.v = 0; end.a is never 0 (the natural system is regular).
  const B: Point = [-end.v[0] / end.a, -end.v[1] / end.a];
  const controls = forms.map((f) => valueAt(f, B));
  const solved = solveCubicSplineC2System(p).controls;
  let solverDifference = 0;
  controls.forEach((c, j) =>
    c.forEach(
      (v, d) => (solverDifference = Math.max(solverDifference, Math.abs(v - solved[j][d]))),
    ),
  );
  return { forms, end, B, controls, solverDifference };
}

/**
 * How many choices a spline of n pieces of degree d leaves: dn + 1 control
 * points (neighbours share their joint), n + 1 fixed by the points, and C¹ …
 * C^(d−1) at each of the n − 1 inner joints. What is left is d − 1, whatever n.
 */
export function degreeCount(d: number, n: number) {
  const unknowns = d * n + 1;
  const interpolation = n + 1;
  const smoothness = (d - 1) * (n - 1);
  return { unknowns, interpolation, smoothness, free: unknowns - interpolation - smoothness };
}

/**
 * The piece `piece` continued past its end: the Bézier control points of
 * P(1 + t), t ∈ [0, 1]. A next piece of the same degree with the same value
 * and all its derivatives at the joint can only be this one (its Taylor
 * expansion there is the whole polynomial).
 */
export function continuation(piece: readonly Point[]): Point[] {
  const a = bezierToPowerBasis(piece);
  // P(1 + t) = Σⱼ aⱼ (1 + t)ʲ = Σₖ tᵏ Σⱼ₌ₖ C(j, k) aⱼ.
  const shifted = a.map((_, k) =>
    a.slice(k).reduce<Point>(
      (sum, aj, offset) => sum.map((s, d) => s + binomial(k + offset, k) * aj[d]),
      a[0].map(() => 0),
    ),
  );
  return powerBasisToBezier(shifted);
}
