import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { comparedIndex, curveNear, highlightedIndex } from './hover';
import lesson from './lesson';
import type { BlendingModel } from './model';
import { checkScript } from '../../kit/scriptChecks';
import { type BlendingState, schema } from './state';

// Values worked out by hand for the lecture's cubic P0 = (0, 0), P1 = (1, 2),
// P2 = (3, 2), P3 = (4, 0), with W(3, i, μ) = C(3, i) μⁱ (1 − μ)³⁻ⁱ.

const cubic: BlendingState = defaultsOf(schema); // μ = 0.5, no comparison
/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: BlendingState) => lesson.derive(s) as BlendingModel;
const stepCount = (s: BlendingState) => lesson.steps!.count(s);
const describeStep = (s: BlendingState, k: number) => lesson.steps!.describe(s, k);
const stepFormula = (m: BlendingModel, s: BlendingState) => lesson.steps!.formula!(m, s);
/** What a step shows: how many weights, P(μ), the curve, the comparison. */
const revealed = (s: BlendingState) => {
  const { drawn } = derive(s);
  return {
    weights: drawn.weights,
    point: drawn.point,
    curve: drawn.curve,
    compared: drawn.compared > 0,
  };
};
const close = (actual: readonly number[], expected: readonly number[], digits = 12) =>
  expected.forEach((v, i) => expect(actual[i]).toBeCloseTo(v, digits));

describe('derive (blending)', () => {
  it('weights the cubic 1/8, 3/8, 3/8, 1/8 at μ = ½, and P(½) = (2, 1.5)', () => {
    const m = derive(cubic);
    expect(m.n).toBe(3);
    expect(m.weights).toEqual([0.125, 0.375, 0.375, 0.125]);
    expect(m.sum).toBe(1);
    // ((0 + 3·1 + 3·3 + 4) / 8, (0 + 3·2 + 3·2 + 0) / 8)
    close(m.point, [2, 1.5]);
    close(m.centre, [2, 1.5]);
  });

  it('has the matrix of (1−u)³, 3u(1−u)², 3u²(1−u), u³ by powers of u', () => {
    expect(derive(cubic).matrix).toEqual([
      [1, 0, 0, 0],
      [-3, 3, 0, 0],
      [3, -6, 3, 0],
      [-1, 3, -3, 1],
    ]);
  });

  it('compares with Hermite: H₃ dips to −4/27 at μ = 2/3; the end tangents are 3(P₁ − P₀), 3(P₃ − P₂)', () => {
    const m = derive({ ...cubic, comparison: 'hermite' });
    const c = m.compared!;
    expect(c.labels).toEqual(['H_0', 'H_1', 'H_2', 'H_3']);
    // H0 weighs x0 = P0, H1 weighs x1 = P3: they share those points' colours.
    expect(c.colors).toEqual([0, 3, 1, 2]);
    expect(c.samples.lowest.index).toBe(3);
    expect(c.samples.lowest.value).toBeCloseTo(-4 / 27, 5);
    expect(c.samples.lowest.mu).toBeCloseTo(2 / 3, 2);
    close(c.atMu, [0.5, 0.5, 0.125, -0.125]);
    expect(c.arrows).toEqual([
      [
        [0, 0],
        [3, 6],
      ],
      [
        [4, 0],
        [7, -6],
      ],
    ]);
    // The plot reaches below 0 to show the dip. The arrows are drawn at half
    // length, tips (1.5, 3) and (5.5, −3), and the fit shows those, not (3, 6)
    // and (7, −6), which left the curve small in the middle of the view.
    expect(m.plotBounds.minY).toBeLessThan(-4 / 27);
    expect(m.curveBounds).toEqual({ minX: 0, minY: -3, maxX: 5.5, maxY: 3 });
  });

  it('compares with the uniform B-spline: B(0) = (P₀ + 4P₁ + P₂) / 6, nothing negative', () => {
    const c = derive({ ...cubic, mu: 0, comparison: 'bspline' }).compared!;
    close(c.point!.at, [7 / 6, 10 / 6]);
    expect(c.point!.label).toBe('B(μ)');
    expect(c.samples.lowest.value).toBeGreaterThanOrEqual(0);
    close(c.atMu, [1 / 6, 4 / 6, 1 / 6, 0]);
  });

  it('compares with Lagrange: through P₁ at its node μ = 1/6, outside the hull, weights below 0', () => {
    const steps: BlendingState = {
      p: [
        [0, 0],
        [1, 0],
        [2, 0],
        [3, 1.5],
        [4, 3],
        [5, 3],
        [6, 3],
      ],
      mu: 1 / 6,
      comparison: 'lagrange',
      step: 0,
    };
    const c = derive(steps).compared!;
    close(c.point!.at, [1, 0]);
    close(c.atMu, [0, 1, 0, 0, 0, 0, 0]);
    expect(c.sum).toBeCloseTo(1, 12);
    expect(c.samples.lowest.value).toBeLessThan(0);
    expect(c.outside).toBeGreaterThan(0);
    // The curve passes through every control point, at μ = i/6.
    expect(c.curve).toHaveLength(401);
  });

  it('has nothing to compare with by default', () => {
    const m = derive(cubic);
    expect(m.compared).toBeNull();
    expect(m.plotBounds).toEqual({ minX: 0, maxX: 1, minY: -0.04, maxY: 1.16 });
    expect(m.handleY).toBeCloseTo(1.1, 12);
  });
});

describe('the script (blending)', () => {
  it('steps from the points through each weight, P(μ), the curve and the comparison, and draws more at the end', () => {
    checkScript(lesson);
  });

  it('reveals the weights one by one: N + 3 steps; Hermite’s comparison takes 7 of its own', () => {
    expect(stepCount(cubic)).toBe(6);
    expect(stepCount({ ...cubic, comparison: 'hermite' })).toBe(7);
    expect(revealed({ ...cubic, step: 0 })).toEqual({
      weights: 0,
      point: false,
      curve: false,
      compared: false,
    });
    expect(revealed({ ...cubic, step: 2 })).toEqual({
      weights: 2,
      point: false,
      curve: false,
      compared: false,
    });
    expect(revealed({ ...cubic, step: 5 })).toEqual({
      weights: 4,
      point: true,
      curve: false,
      compared: false,
    });
    expect(revealed({ ...cubic, step: 6 })).toEqual({
      weights: 4,
      point: true,
      curve: true,
      compared: false,
    });
    expect(describeStep(cubic, 2)).toBe('The weight of P₁: W(3, 1, μ), largest at μ = 1/3');
    // W(3, 1, ½) = 3 · ½ · ¼ = 0.375.
    expect(stepFormula(derive({ ...cubic, step: 2 }), { ...cubic, step: 2 })).toMatch(/= 0\.3750$/);
  });

  it('says what coincident and collinear control points do to the curve', () => {
    const line = derive({
      ...cubic,
      p: [
        [0, 0],
        [1, 1],
        [3, 3],
        [2, 2],
      ],
    });
    expect(line.note).toMatch(/^The control points lie on one line/);
    const twice = derive({
      ...cubic,
      p: [
        [0, 0],
        [1, 2],
        [1, 2],
        [4, 0],
      ],
    });
    expect(twice.note).toMatch(/^P1 = P2: that spot carries the weights of both/);
    const spot = derive({
      ...cubic,
      p: [
        [1, 1],
        [1, 1],
        [1, 1],
      ],
    });
    expect(spot.note).toMatch(/^All control points are on one spot/);
    expect(derive(cubic).note).toBeNull();
  });
});

describe('hover ids', () => {
  it('a handle p3 and a basis curve w3 both mean control point 3; c1 is a compared function', () => {
    expect(highlightedIndex('p3')).toBe(3);
    expect(highlightedIndex('w2')).toBe(2);
    expect(highlightedIndex('c1')).toBeNull();
    expect(comparedIndex('c1')).toBe(1);
    expect(comparedIndex(null)).toBeNull();
  });

  it('finds the curve under the pointer: W(3, 0, 0) = 1, W(3, 3, 1) = 1', () => {
    const m = derive(cubic);
    expect(curveNear(m, [0, 1], 0.05)).toBe('w0');
    expect(curveNear(m, [1, 0.98], 0.05)).toBe('w3');
    expect(curveNear(m, [0.5, 0.9], 0.05)).toBeNull();
  });
});

describe('the weights the control points wear', () => {
  const last = (s: BlendingState) => ({ ...s, step: stepCount(s) });

  it('are Bernstein’s until a comparison’s values at μ, then the compared functions’ at the points they weight', () => {
    // The lecture's cubic at μ = ½: 1/8, 3/8, 3/8, 1/8 before the last step of each comparison.
    for (const comparison of ['hermite', 'bspline', 'lagrange'] as const) {
      const s = { ...cubic, comparison };
      expect(derive({ ...last(s), step: stepCount(s) - 1 }).pointWeights).toEqual([
        0.125, 0.375, 0.375, 0.125,
      ]);
    }
    // Hermite at ½: H₀ = 2μ³ − 3μ² + 1 = ½ at P₀, H₁ = −2μ³ + 3μ² = ½ at P₃; P₁ and P₂ are not its data.
    expect(derive(last({ ...cubic, comparison: 'hermite' })).pointWeights).toEqual([
      0.5,
      null,
      null,
      0.5,
    ]);
    // The uniform cubic B-spline at ½: (1 − μ)³/6, (3μ³ − 6μ² + 4)/6, (−3μ³ + 3μ² + 3μ + 1)/6, μ³/6.
    close(derive(last({ ...cubic, comparison: 'bspline' })).pointWeights as number[], [
      1 / 48,
      23 / 48,
      23 / 48,
      1 / 48,
    ]);
  });

  it('at Lagrange’s values at μ = 0.1 for degree 6, are Lᵢ(0.1), negative ones among them', () => {
    const p: BlendingState['p'] = [0, 1, 2, 3, 4, 5, 6].map((i) => [i, i % 2]);
    const s = { ...cubic, p, mu: 0.1, comparison: 'lagrange' as const };
    // Lᵢ(μ) = Π_{j ≠ i} (μ − j/6) / (i/6 − j/6), worked here from the definition.
    const lagrange = (i: number, mu: number) =>
      [0, 1, 2, 3, 4, 5, 6]
        .filter((j) => j !== i)
        .reduce((product, j) => (product * (mu - j / 6)) / (i / 6 - j / 6), 1);
    const weights = derive(last(s)).pointWeights as number[];
    close(
      weights,
      [0, 1, 2, 3, 4, 5, 6].map((i) => lagrange(i, 0.1)),
    );
    expect(weights.some((w) => w < 0)).toBe(true);
  });
});
