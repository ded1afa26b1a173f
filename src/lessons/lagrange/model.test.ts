import { describe, expect, it } from 'vitest';
import { type LagrangeModel, SAMPLES } from './model';
import { lagrangeBasis } from '../../math';
import { checkScript } from '../../kit/scriptChecks';
import lesson from './lesson';
import { DEFAULT_POINTS, type LagrangeState, RUNGE_POINTS } from './state';

const state = (over: Partial<LagrangeState> = {}): LagrangeState => ({
  points: DEFAULT_POINTS,
  t: 0.4,
  spacing: 'uniform',
  spline: false,
  step: 0,
  ...over,
});

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: LagrangeState) => lesson.derive(s) as LagrangeModel;
const stepCount = (s: LagrangeState) => lesson.steps!.count(s);
const describeStep = (s: LagrangeState, k: number) => lesson.steps!.describe(s, k);
/** What a step shows: how many Lₖ, the polynomial, the spline. */
const revealed = (s: LagrangeState) => {
  const { shown } = derive(s);
  return { basis: shown.count('basis'), curve: shown.has('curve'), pieces: shown.count('piece') };
};

describe('Lagrange model', () => {
  it('weighs five equally spaced points at t = 2/5 by the product formula', () => {
    // t_k = 0, 1/4, 1/2, 3/4, 1. L0(2/5) = (3/20)(−1/10)(−7/20)(−3/5) / ((−1/4)(−1/2)(−3/4)(−1))
    // = (−63/20000) / (3/32) = −0.0336; L4(2/5) = (2/5)(3/20)(−1/10)(−7/20) / (1 · 3/4 · 1/2 · 1/4) = 0.0224.
    const m = derive(state());
    expect(m.n).toBe(4);
    expect(m.ts).toEqual([0, 0.25, 0.5, 0.75, 1]);
    expect(m.weights[0]).toBeCloseTo(-0.0336, 12);
    expect(m.weights[4]).toBeCloseTo(0.0224, 12);
    expect(m.weightSum).toBeCloseTo(1, 12);
  });

  it('puts P(1/2) of two points at their midpoint, each weighing one half', () => {
    const m = derive(
      state({
        points: [
          [0, 0],
          [3, 2],
        ],
        t: 0.5,
      }),
    );
    expect(m.weights).toEqual([0.5, 0.5]);
    expect(m.at).toEqual([1.5, 1]);
    // A line never leaves [0, 1]: Σ|L_k| = (1 − t) + t = 1, and the plot keeps its margins.
    expect(m.lebesgue.value).toBeCloseTo(1, 12);
    expect(m.plotBounds).toEqual({ minX: 0, maxX: 1, minY: -0.3 * 1.05, maxY: 1.2 * 1.05 });
    expect(m.basisCut).toBe(false);
  });

  it('gives chord-length t_k by the lengths of the polygon', () => {
    // Gaps 5, 5 and 10 (3-4-5 triangles): t = 0, 1/4, 1/2, 1.
    const m = derive(
      state({
        points: [
          [0, 0],
          [3, 4],
          [6, 8],
          [12, 16],
        ],
        spacing: 'chord',
      }),
    );
    expect(m.ts).toEqual([0, 0.25, 0.5, 1]);
    expect(m.collapsed).toBeNull();
  });

  it('falls back to equal spacing when two neighbours coincide, and says why', () => {
    const m = derive(
      state({
        points: [
          [0, 0],
          [1, 2],
          [1, 2],
          [4, 1],
        ],
        spacing: 'chord',
      }),
    );
    expect(m.collapsed).toEqual([1, 2]);
    expect(m.ts).toEqual([0, 1 / 3, 2 / 3, 1]);
    expect(m.collapsedWarning).toMatch(/^P1 and P2 are the same point, so chord length/);
    expect(m.collapsedNote).toMatch(/^P1 and P2 coincide/);
  });

  it('samples the curve at the basis’s t, through every point at its t_k', () => {
    const m = derive(state());
    expect(m.curve).toHaveLength(2 * (SAMPLES + 1));
    // t_k = k/4 is sample i = k · SAMPLES / 4.
    DEFAULT_POINTS.forEach((point, k) => {
      const i = (k * SAMPLES) / 4;
      expect(m.curve[2 * i]).toBeCloseTo(point[0], 12);
      expect(m.curve[2 * i + 1]).toBeCloseTo(point[1], 12);
    });
  });

  it('draws the spline only when asked, one cubic per gap', () => {
    expect(derive(state()).comparison).toBeNull();
    expect(derive(state({ spline: true })).comparison!.segments).toHaveLength(4);
  });

  it('cuts the basis plot at ±3 when the weights swing wider (Runge)', () => {
    const ts = Array.from({ length: 12 }, (_, k) => [k, (k % 2) * 0.1]);
    const m = derive(state({ points: ts }));
    expect(m.plotBounds.minY).toBe(-3);
    expect(m.plotBounds.maxY).toBe(3);
    expect(m.basisCut).toBe(true);
    for (const pieces of m.basisPieces)
      for (const piece of pieces)
        for (let i = 1; i < piece.length; i += 2) expect(Math.abs(piece[i])).toBeLessThanOrEqual(3);
  });
});

describe('the script (Lagrange)', () => {
  it('steps from the points through each Lₖ to the polynomial and the spline, drawing more at the end', () => {
    checkScript(lesson);
  });

  it('reveals L₀ … Ln one by one, then the polynomial; beside the spline, its pieces one by one', () => {
    expect(stepCount(state())).toBe(6);
    // The points, the polynomial, the gradients, four pieces, the coupling.
    expect(stepCount(state({ spline: true }))).toBe(7);
    expect(revealed(state({ step: 3 }))).toEqual({ basis: 3, curve: false, pieces: 0 });
    expect(revealed(state({ step: 1, spline: true }))).toEqual({
      basis: 0,
      curve: true,
      pieces: 0,
    });
    expect(revealed(state({ step: 4, spline: true }))).toEqual({
      basis: 0,
      curve: true,
      pieces: 2,
    });
    expect(describeStep(state(), 2)).toBe('L₁(t): 1 at its own t₁, 0 at every other tₖ');
    // Sixteen points and the spline: 3 + 15 pieces, still at most 20 presses.
    const many = Array.from({ length: 16 }, (_, k) => [k, k % 3]);
    expect(stepCount(state({ points: many, spline: true }))).toBe(18);
  });

  it('Runge: eleven points equally spaced on y = 4/(1 + x²); the polynomial wiggles past 7 near the ends', () => {
    expect(RUNGE_POINTS.map((p) => p[0])).toEqual([-5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5]);
    expect(RUNGE_POINTS[5][1]).toBe(4);
    // Between the first two nodes, at x = −4.5 (t = 0.05), by the product formula directly:
    // the classic interpolant of 1/(1 + x²) is above 1.5 there (the bump itself is 0.047).
    const ts = RUNGE_POINTS.map((_, k) => k / 10);
    const y = lagrangeBasis(ts, 0.05).reduce((sum, w, k) => sum + w * RUNGE_POINTS[k][1], 0);
    expect(y).toBeGreaterThan(6);
    const m = derive(state({ points: RUNGE_POINTS, t: 0.05 }));
    expect(m.at[1]).toBeCloseTo(y, 10);
    expect(m.at[0]).toBeCloseTo(-4.5, 10);
  });

  it('says what coincident and collinear points do', () => {
    expect(
      derive(
        state({
          points: [
            [0, 0],
            [1, 1],
            [3, 3],
          ],
        }),
      ).note,
    ).toMatch(/^The points lie on one line/);
    expect(
      derive(
        state({
          points: [
            [0, 0],
            [1, 2],
            [1, 2],
            [4, 1],
          ],
        }),
      ).note,
    ).toMatch(/^P1 = P2: the polynomial must be at that spot at two values of t/);
    expect(
      derive(
        state({
          points: [
            [2, 2],
            [2, 2],
          ],
        }),
      ).note,
    ).toMatch(/^All points are on one spot/);
  });
});
