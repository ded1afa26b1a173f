import { describe, expect, it } from 'vitest';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import lesson from './lesson';
import type { LagrangeModel } from './model';
import { interpolatedPoints } from './points';
import { interpolation } from './script';
import { DEFAULT_POINTS, type LagrangeState, schema } from './state';

const state = (changes: Partial<LagrangeState> = {}): LagrangeState => ({
  ...defaultsOf(schema),
  ...changes,
});
const derive = (s: LagrangeState) => lesson.derive(s) as LagrangeModel;
const caption = (s: LagrangeState) => lesson.steps!.describe(s, s.step);
const formula = (s: LagrangeState) => lesson.steps!.formula!(derive(s), s);

describe('the named steps of Lagrange interpolation', () => {
  it('names each press: the points, L₀ … L₄, the polynomial (and the spline when compared)', () => {
    const names = (s: LagrangeState) =>
      Array.from({ length: interpolation.lastStep(s) + 1 }, (_, k) => {
        const shown = interpolation.shown(s, k);
        return shown.index ? `${shown.name}${shown.index}` : shown.name;
      });
    expect(names(state())).toEqual([
      'points',
      'basis1',
      'basis2',
      'basis3',
      'basis4',
      'basis5',
      'curve',
    ]);
    expect(interpolation.stepOf(state(), 'curve')).toBe(6);
    expect(interpolation.stepOf(state(), 'piece')).toBe(-1);
  });

  it('step 0: the five points and their equally spaced t_k', () => {
    const s = state({ step: 0 });
    expect(caption(s)).toBe('The 5 points P₀ … P₄ to pass through, in order');
    expect(formula(s)).toBe('t_k = 0.000,\\ 0.250,\\ 0.500,\\ 0.750,\\ 1.000');
    // Seven points or more: the first and the last value only.
    const many = Array.from({ length: 7 }, (_, k) => [k, k % 2]);
    expect(formula(state({ points: many, step: 0 }))).toBe('t_k = 0.000,\\ \\dots,\\ 1.000');
  });

  it('each Lₖ with its value at t, worked by the product formula', () => {
    // L0(2/5) = (2/5 − 1/4)(2/5 − 1/2)(2/5 − 3/4)(2/5 − 1) / ((−1/4)(−1/2)(−3/4)(−1)) = −0.0336.
    expect(caption(state({ step: 1 }))).toBe('L₀(t): 1 at its own t₀, 0 at every other tₖ');
    expect(formula(state({ step: 1 }))).toBe(
      'L_{0}(t) = \\prod_{j \\ne 0} \\frac{t - t_j}{t_{0} - t_j},\\qquad L_{0}(0.40) = -0.0336',
    );
    // L2(2/5) = (2/5)(3/20)(−7/20)(−3/5) / ((1/2)(1/4)(−1/4)(−1/2)) = 0.0126 / 0.015625 = 0.8064.
    expect(formula(state({ step: 3 }))).toMatch(/L_\{2\}\(0\.40\) = 0\.8064$/);
    // L3(2/5) = 0.0036 / (−0.0234375) = −0.1536.
    expect(formula(state({ step: 4 }))).toMatch(/L_\{3\}\(0\.40\) = -0\.1536$/);
    expect(caption(state({ step: 5 }))).toBe('L₄(t): 1 at its own t₄, 0 at every other tₖ');
  });

  it('the polynomial: P(2/5) = Σ Lₖ(2/5) Pₖ, worked by hand', () => {
    // Weights −0.0336, 0.3584, 0.8064, −0.1536, 0.0224 on (0, 0), (1, 2), (3, 2.5), (4.5, 1), (6, 2):
    // x = 0.3584 + 2.4192 − 0.6912 + 0.1344 = 2.2208, y = 0.7168 + 2.016 − 0.1536 + 0.0448 = 2.624.
    const s = state({ step: 6 });
    expect(caption(s)).toBe(
      'The polynomial of degree 4: P(t) = Σ Lₖ(t) Pₖ passes through every point',
    );
    expect(formula(s)).toBe('P(0.40) = \\sum_{k=0}^{4} L_k(0.40)\\,P_k = (2.221,\\ 2.624)');
  });

  it('a step costs no new sampling: the basis and the spline are kept while the points are', () => {
    const s = state({ spline: true, step: 2 });
    const a = derive(s);
    const b = derive({ ...s, step: 7 });
    expect(b.basis).toBe(a.basis);
    expect(b.curve).toBe(a.curve);
    expect(b.comparison).toBe(a.comparison);
    // A new t weighs the points again, on the same basis.
    const c = derive({ ...s, t: 0.9 });
    expect(c.basis).toBe(a.basis);
    expect(c.weights).not.toEqual(a.weights);
  });
});

describe('the points and the link', () => {
  it('adds a double-clicked point after the last, and keeps the script shown to its end', () => {
    const end = state({ step: 6 });
    const added = interpolatedPoints.add(end, [2, 0])!;
    expect(added.points).toEqual([...DEFAULT_POINTS, [2, 0]]);
    expect(added.step).toBe(7);
    expect(interpolatedPoints.add(state({ step: 2 }), [2, 0])!.step).toBe(2);
    const removed = interpolatedPoints.remove(end, 1)!;
    expect(removed.points).toHaveLength(4);
    expect(removed.step).toBe(5);
  });

  it('names every point, each on its own, and only the ends past nine points', () => {
    const stacked = interpolatedPoints.handles(
      state({
        points: [
          [0, 0],
          [1, 2],
          [1, 2],
          [4, 1],
        ],
      }),
    );
    expect(stacked.map((h) => [h.id, h.label, h.showLabel])).toEqual([
      ['p0', 'P_{0}', true],
      ['p1', 'P_{1}', true],
      ['p2', 'P_{2}', true],
      ['p3', 'P_{3}', true],
    ]);
    const ten = Array.from({ length: 10 }, (_, k) => [k, k % 2]);
    const shown = interpolatedPoints.handles(state({ points: ten })).map((h) => h.showLabel);
    expect(shown).toEqual([true, ...Array(8).fill(false), true]);
  });

  it('keeps the link’s keys and their order: p, t, spacing, spline, step', () => {
    expect(encodeState(schema, defaultsOf(schema))).toBe(
      'p=0,0;1,2;3,2.5;4.5,1;6,2&t=0.4&spacing=uniform&spline=0&step=0',
    );
    const { state: opened, issues } = decodeState(
      schema,
      'p=0,0;1,2;1,2;4,1&spacing=chord&spline=1&step=3',
    );
    expect(issues).toEqual([]);
    expect(opened).toEqual(
      state({
        points: [
          [0, 0],
          [1, 2],
          [1, 2],
          [4, 1],
        ],
        spacing: 'chord',
        spline: true,
        step: 3,
      }),
    );
  });
});
