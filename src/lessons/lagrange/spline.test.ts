import { describe, expect, it } from 'vitest';
import { lagrangeBasis, naturalCubicTangents, type Point } from '../../math';
import { drawState } from '../../kit/scriptChecks';
import { makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';
import lesson from './lesson';
import type { LagrangeModel } from './model';
import { comparison } from './script';
import { DEFAULT_POINTS, type LagrangeState, RUNGE_POINTS } from './state';
import { BASIS_SLIP, rungeText } from './text';

const state = (over: Partial<LagrangeState> = {}): LagrangeState => ({
  points: DEFAULT_POINTS,
  t: 0.4,
  spacing: 'uniform',
  spline: false,
  step: 0,
  ...over,
});
const derive = (s: LagrangeState) => lesson.derive(s) as LagrangeModel;
const runge = state({ points: RUNGE_POINTS, spline: true, t: 0.05 });
const moved = (points: Point[], k: number): Point[] =>
  points.map((p, i) => (i === k ? [p[0], p[1] + 1] : p));

describe('the natural spline is global (issue #19)', () => {
  it('moving one point changes every gradient D, by the maths alone', () => {
    // Off the middle (the middle point of a symmetric row leaves its own D at 0).
    for (const [points, k] of [
      [RUNGE_POINTS, 4],
      [DEFAULT_POINTS, 1],
    ] as const) {
      const before = naturalCubicTangents(points);
      const after = naturalCubicTangents(moved(points, k));
      before.forEach((d, i) =>
        expect(Math.hypot(after[i][0] - d[0], after[i][1] - d[1])).toBeGreaterThan(1e-6),
      );
    }
  });

  it('the last step moves P₄ of the Runge points and says every gradient changes, as the maths does', () => {
    const last = { ...runge, step: lesson.steps!.count(runge) };
    const c = derive(last).comparison!;
    expect(c.moved).toBe(4);
    const before = naturalCubicTangents(RUNGE_POINTS);
    const after = naturalCubicTangents(moved(RUNGE_POINTS, 4));
    c.gradientChange.forEach((change, i) =>
      expect(change).toBeCloseTo(
        Math.hypot(after[i][0] - before[i][0], after[i][1] - before[i][1]),
        12,
      ),
    );
    expect(lesson.steps!.describe(last, last.step)).toBe(
      'Move P₄ up by 1 (dashed): all 11 gradients change, so the pieces are coupled',
    );
  });

  it('no sentence says the spline’s pieces listen only to nearby points', () => {
    const text = rungeText({ value: 29.9, t: 0.03 });
    expect(text).not.toMatch(/only listen|nearby points|neighbours/);
    expect(text).toMatch(/moving one point changes every gradient and every piece/);
    expect(text).toMatch(/Local control.* is what piecewise Bézier curves and B-splines give/);
    for (let k = 0; k <= lesson.steps!.count(runge); k++)
      expect(lesson.steps!.describe({ ...runge, step: k }, k)).not.toMatch(
        /only|neighbour|local\b/,
      );
  });
});

describe('every press shows something new, and no scene replays another’s (issue #20)', () => {
  it('the Runge–spline scene starts at the points and shows the polynomial in one press', () => {
    const names = Array.from(
      { length: comparison.lastStep(runge) + 1 },
      (_, k) => comparison.shown(runge, k).name,
    );
    expect(names).toEqual(['points', 'curve', 'gradients', ...Array(10).fill('piece'), 'coupled']);
    // The recorded link's last step (13) is still the last step, now the coupling.
    expect(lesson.steps!.count(runge)).toBe(13);
  });

  it('each step of every scene draws something the step before did not', () => {
    for (const scene of lesson.scenes!) {
      const opened = { ...(scene.apply(state()) as LagrangeState), step: 0 };
      let before = drawState(lesson, opened).svg;
      for (let k = 1; k <= lesson.steps!.count(opened); k++) {
        const now = drawState(lesson, { ...opened, step: k }).svg;
        expect(now, `${scene.id} step ${k}`).not.toBe(before);
        before = now;
      }
    }
  });

  it('on each piece, the polynomial strays most at the ends (over 7 on the first piece, by the product formula)', () => {
    const c = derive(runge).comparison!;
    // By hand at t = 0.02 (x = −4.8): Σ Lₖ(0.02) yₖ against the spline's first piece at μ = 0.2.
    const ts = RUNGE_POINTS.map((_, k) => k / 10);
    const y = lagrangeBasis(ts, 0.02).reduce((sum, w, k) => sum + w * RUNGE_POINTS[k][1], 0);
    expect(y).toBeGreaterThan(7.2);
    expect(c.gaps[0]).toBeGreaterThan(7.2);
    expect(c.gaps[0]).toBeCloseTo(c.gaps[9], 9);
    expect(c.gaps[4]).toBeLessThan(0.2);
  });
});

describe('what the panel says about the notes', () => {
  it('the slip in the continuation notes: Lₖ(tᵢ) is 1 if k = i and 0 otherwise, Lₖ(t) is not', () => {
    expect(BASIS_SLIP.written).toMatch(/Lₖ\(t\) is 1 if k = i/);
    expect(BASIS_SLIP.correct).toMatch(/Lₖ\(tᵢ\) = 1 if k = i and Lₖ\(tᵢ\) = 0 if k ≠ i/);
    const ts = [0, 0.25, 0.5, 0.75, 1];
    ts.forEach((ti, i) =>
      lagrangeBasis(ts, ti).forEach((w, k) => expect(w).toBeCloseTo(k === i ? 1 : 0, 12)),
    );
    // Between the nodes, a value that is neither: L0(0.4) = −0.0336.
    expect(lagrangeBasis(ts, 0.4)[0]).toBeCloseTo(-0.0336, 12);
  });
});

describe('the view fits the points (issue #20)', () => {
  // The curve figure as the page fits it, at the desk and in presenter view (1920 × 385).
  const fitted = (s: LagrangeState, width: number, height: number, projector: boolean) => {
    const view = new Viewport();
    view.resize(width, height);
    const theme = makeTheme(false, projector);
    const room = theme.sizes.handle * 2 + theme.sizes.label * 1.6;
    view.fit(
      lesson.figures[0].bounds(derive(s)),
      Math.min(room, 0.12 * Math.min(width, height)),
      true,
    );
    return s.points.map((p) => view.toScreen(p));
  };

  it('Runge: the eleven points fill most of the width, and every one is on screen', () => {
    for (const [width, height, projector, share] of [
      [935, 420, false, 0.55],
      [1920, 385, true, 0.24],
    ] as const) {
      const screen = fitted(runge, width, height, projector);
      const xs = screen.map(([x]) => x);
      expect((Math.max(...xs) - Math.min(...xs)) / width).toBeGreaterThan(share);
      for (const [x, y] of screen) {
        expect(x).toBeGreaterThan(0);
        expect(x).toBeLessThan(width);
        expect(y).toBeGreaterThan(0);
        expect(y).toBeLessThan(height);
      }
    }
  });
});
