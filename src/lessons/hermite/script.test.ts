import { describe, expect, it } from 'vitest';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import { curveFigure } from './figure';
import lesson from './lesson';
import { type HermiteModel, spline } from './model';
import { controlPoints, gradientTips } from './points';
import { construction } from './script';
import { type HermiteState, schema } from './state';

const derive = (s: HermiteState) => lesson.derive(s) as HermiteModel;
const caption = (s: HermiteState) => lesson.steps!.describe(s, s.step);
const formula = (s: HermiteState) => lesson.steps!.formula!(derive(s), s);

/** The lecture patch: P0 = (0, 0), P1 = (4, 0), D0 = (3, 4.5), D1 = (3, −4.5), μ = 0.3. */
const lecture = (changes: Partial<HermiteState> = {}): HermiteState => ({
  ...defaultsOf(schema),
  ...changes,
});
const atStep = (name: Parameters<typeof construction.stepOf>[1], changes = {}) => {
  const s = lecture(changes);
  return { ...s, step: construction.stepOf(s, name) };
};

describe('the script of Hermite patches, by named step', () => {
  it('names its steps in teaching order, the patch step once per patch, the Bézier view only when on', () => {
    const names = (s: HermiteState) =>
      Array.from({ length: construction.lastStep(s) + 1 }, (_, k) => construction.shown(s, k).name);
    expect(names(lecture())).toEqual([
      'points',
      'gradients',
      'pointWeights',
      'gradientWeights',
      'patch',
      'pointAtMu',
    ]);
    expect(names(lecture({ bezier: true })).at(-1)).toBe('bezier');
    const three = lecture({
      points: [
        [0, 0],
        [1, 1],
        [2, 0],
      ],
      handGradients: [
        [1, 0],
        [1, 0],
        [1, 0],
      ],
    });
    expect(names(three).filter((name) => name === 'patch')).toHaveLength(2);
  });

  it('says what each step shows, in words', () => {
    expect(caption(atStep('points'))).toBe('The points P0 … P1: where the curve must pass');
    expect(caption(atStep('gradients'))).toBe(
      'The gradients D0 … D1, set by hand (arrows drawn a third as long)',
    );
    expect(caption(atStep('gradients', { mode: 'catmull-rom' }))).toBe(
      'The gradients D0 … D1 from the neighbours: Dₖ = (Pₖ₊₁ − Pₖ₋₁)/2, zero at both ends',
    );
    expect(caption(atStep('pointWeights'))).toBe('H0 and H1 weight the end points: H0 + H1 = 1');
    expect(caption(atStep('patch'))).toBe(
      'Patch 1 of 1, from P0 to P1: the patch matrix turns its four conditions into a0 … a3',
    );
    expect(caption(atStep('pointAtMu'))).toBe('P(μ) on patch 1: H0 P + H1 P + H2 D + H3 D');
    expect(caption(atStep('bezier', { bezier: true }))).toBe(
      'The same patch as a Bézier curve: its inner control points are the arrow tips, P ± D/3',
    );
  });

  it('gives each step its formula with the numbers worked by hand', () => {
    expect(formula(atStep('gradients'))).toBe("P'(0) = D_i,\\qquad P'(1) = D_{i+1}");
    // a2 = 3(P1 − P0) − 2D0 − D1 = (3, −4.5), a3 = 2(P0 − P1) + D0 + D1 = (−2, 0).
    expect(formula(atStep('patch'))).toMatch(
      /= \\begin\{pmatrix\}0\.000 & 0\.000\\\\3\.000 & 4\.500\\\\3\.000 & -4\.500\\\\-2\.000 & 0\.000\\end\{pmatrix\}$/,
    );
    // H(0.3) = (0.784, 0.216, 0.147, −0.063): P(0.3) = 0.216·(4, 0) + 0.147·(3, 4.5) − 0.063·(3, −4.5).
    expect(formula(atStep('pointAtMu'))).toBe(
      'P(0.300) = 0.784\\,P_{0} + 0.216\\,P_{1} + 0.147\\,D_{0} - 0.063\\,D_{1} = (1.116,\\ 0.945)',
    );
    // B1 = P0 + D0/3 = (1, 1.5), B2 = P1 − D1/3 = (3, 1.5).
    expect(formula(atStep('bezier', { bezier: true }))).toBe(
      'B_0 = (0.00,\\ 0.00),\\quad B_1 = (1.00,\\ 1.50),\\quad B_2 = (3.00,\\ 1.50),\\quad B_3 = (4.00,\\ 0.00)',
    );
  });

  it('traces P(μ) only once the step shows it', () => {
    expect(curveFigure.trail!(derive(atStep('patch')))).toBeNull();
    const p = curveFigure.trail!(derive(atStep('pointAtMu')))!;
    expect(p[0]).toBeCloseTo(1.116, 12);
    expect(p[1]).toBeCloseTo(0.945, 12);
  });

  it('solves the spline once for every step of one state', () => {
    const s = lecture();
    const models = [0, 3, 5].map((step) => derive({ ...s, step }));
    expect(models[1].segments).toBe(models[0].segments);
    expect(models[2].joins).toBe(models[0].joins);
    expect(spline({ ...s, mu: 0.9 })).toBe(spline(s));
  });
});

describe('the points and their gradients (point lists)', () => {
  const ids = (s: HermiteState) =>
    curveFigure.points!.flatMap((list) => list.handles(s)).map((h) => h.id);

  it('shows the gradients’ tips as handles from the gradients’ step on', () => {
    expect(ids(atStep('points'))).toEqual(['p0', 'p1']);
    expect(ids(atStep('gradients'))).toEqual(['d0', 'd1', 'p0', 'p1']);
    const tip = gradientTips.handles(atStep('gradients'))[0];
    expect([tip.label, tip.position, tip.shape]).toEqual(['D_{0}', [1, 1.5], 'square']);
  });

  it('a dragged tip sets D = 3 (tip − P), by hand, and leaves the other gradient as it was', () => {
    const s = atStep('gradients', { mode: 'catmull-rom' });
    const moved = gradientTips.move(s, 1, [4.5, 1]);
    expect(moved.mode).toBe('hand');
    // Catmull-Rom's D0 of two points is zero; D1 = 3 ((4.5, 1) − (4, 0)) = (1.5, 3).
    expect(moved.handGradients).toEqual([
      [0, 0],
      [1.5, 3],
    ]);
    expect(gradientTips.remove(s, 0)).toBeNull();
  });

  it('adds a point after the last one, heading away from it, and keeps the end in view', () => {
    const end = lecture({ step: construction.lastStep(lecture()) });
    const added = controlPoints.add(end, [6, 2])!;
    expect(added.points).toEqual([...end.points, [6, 2]]);
    expect(added.handGradients.at(-1)).toEqual([2, 2]);
    expect(added.step).toBe(construction.lastStep(added));
    const midway = controlPoints.add(lecture({ step: 1 }), [6, 2])!;
    expect(midway.step).toBe(1);
  });

  it('removes a point with its own gradient, and keeps the chosen patch a patch', () => {
    const three = lecture({
      points: [
        [0, 0],
        [1, 1],
        [2, 0],
      ],
      handGradients: [
        [1, 0],
        [2, 0],
        [3, 0],
      ],
      patch: 1,
    });
    const removed = controlPoints.remove(three, 1)!;
    expect(removed.points).toEqual([
      [0, 0],
      [2, 0],
    ]);
    expect(removed.handGradients).toEqual([
      [1, 0],
      [3, 0],
    ]);
    expect(removed.patch).toBe(0);
    expect(controlPoints.remove(removed, 0)).toBeNull();
  });
});

describe('the link', () => {
  it('keeps its short keys, in the same order, and reads old links to the same state', () => {
    const link = 'p=0,0;4,0&d=3,4.5;3,-4.5&mode=hand&mu=0.3&patch=0&bezier=0&step=0';
    expect(encodeState(schema, lecture())).toBe(link);
    const read = decodeState(schema, 'p=0,0;2,1;4,0&d=1,1;1,0;2,-1&step=3').state;
    expect(read.points).toEqual([
      [0, 0],
      [2, 1],
      [4, 0],
    ]);
    expect(read.handGradients).toEqual([
      [1, 1],
      [1, 0],
      [2, -1],
    ]);
  });
});
