import { describe, expect, it } from 'vitest';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import { curveFigure } from './figure';
import lesson from './lesson';
import { type HermiteModel, spline } from './model';
import { controlPoints, gradientTips } from './points';
import { bezierScript, construction, scriptOf } from './script';
import { type HermiteState, schema } from './state';

const derive = (s: HermiteState) => lesson.derive(s) as HermiteModel;
const caption = (s: HermiteState) => lesson.steps!.describe(s, s.step);
const formula = (s: HermiteState) => lesson.steps!.formula!(derive(s), s);

/** The lecture patch: P0 = (0, 0), P1 = (4, 0), D0 = (3, 4.5), D1 = (3, −4.5), μ = 0.3. */
const lecture = (changes: Partial<HermiteState> = {}): HermiteState => ({
  ...defaultsOf(schema),
  ...changes,
});
type Name = Parameters<typeof construction.stepOf>[1];
const atStep = (name: Name, changes = {}) => {
  const s = lecture(changes);
  return { ...s, step: construction.stepOf(s, name) };
};
const atBezierStep = (name: Name) => {
  const s = lecture({ bezier: true });
  return { ...s, step: bezierScript.stepOf(s, name) };
};
const UNKNOWNS = '\\begin{pmatrix}a_0\\\\a_1\\\\a_2\\\\a_3\\end{pmatrix}';

describe('the script of Hermite patches, by named step', () => {
  const names = (script: typeof construction, s: HermiteState) =>
    Array.from({ length: script.lastStep(s) + 1 }, (_, k) => script.shown(s, k).name);

  it('names its steps in the lecture’s order, the patch step once per patch', () => {
    expect(names(construction, lecture())).toEqual([
      'points',
      'gradients',
      'conditions',
      'matrix',
      'patch',
      'pointWeights',
      'gradientWeights',
      'pointAtMu',
    ]);
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
    expect(names(construction, three).filter((name) => name === 'patch')).toHaveLength(2);
  });

  it('gives the Bézier scene its own steps, which start where its idea starts', () => {
    const bezier = lecture({ bezier: true });
    expect(scriptOf(bezier)).toBe(bezierScript);
    expect(scriptOf(lecture())).toBe(construction);
    expect(names(bezierScript, bezier)).toEqual([
      'bezier',
      'ends',
      'gradients',
      'product',
      'expanded',
      'curve',
      'pointAtMu',
    ]);
    // No step of the construction's first scene is replayed, and no two captions are the same.
    const sceneOne = lecture();
    const captionsOf = (s: HermiteState) =>
      Array.from({ length: lesson.steps!.count(s) + 1 }, (_, step) => caption({ ...s, step }));
    const bezierCaptions = captionsOf(bezier);
    for (const text of captionsOf(sceneOne)) expect(bezierCaptions).not.toContain(text);
    // The lesson's scene "bezier" walks it; the other scenes walk the construction.
    const scenes = lesson.scenes!;
    const opened = (id: string) => scenes.find((scene) => scene.id === id)!.apply(lecture());
    expect(scriptOf(opened('bezier') as HermiteState)).toBe(bezierScript);
    for (const id of ['one', 'long', 'several', 'catmull-rom'])
      expect(scriptOf(opened(id) as HermiteState), id).toBe(construction);
  });

  it('says what each step shows, in words', () => {
    expect(caption(atStep('points'))).toBe('The points P₀ and P₁: where the curve must pass');
    expect(caption(atStep('gradients'))).toBe(
      'The gradients D₀ and D₁, set by hand (arrows drawn a third as long)',
    );
    expect(caption(atStep('gradients', { mode: 'catmull-rom' }))).toBe(
      'The gradients D₀ and D₁ from the neighbours: Dₖ = (Pₖ₊₁ − Pₖ₋₁)/2, zero at both ends',
    );
    expect(caption(atStep('conditions'))).toBe(
      'Patch 1, from P₀ to P₁: its ends at μ = 0 and μ = 1 give four conditions on a₀ … a₃',
    );
    expect(caption(atStep('matrix'))).toBe(
      'The four conditions as one matrix, the data in the order P₀, D₀, P₁, D₁',
    );
    expect(caption(atStep('patch'))).toBe(
      'Patch 1 of 1, from P₀ to P₁: the inverse matrix gives a₀ … a₃',
    );
    expect(caption(atStep('pointWeights'))).toBe(
      'Read down the columns of the inverse: H₀ and H₁ weight the end points, and H₀ + H₁ = 1',
    );
    expect(caption(atStep('pointAtMu'))).toBe('P(μ) on patch 1: H₀P₀ + H₁P₁ + H₂D₀ + H₃D₁');
  });

  it('says each patch of several in one line of presenter view, with the scene beside it (#19)', () => {
    // The "several" scenes: five points, four patches, solved one per press from step 4.
    const scene = lesson.scenes!.find((one) => one.id === 'catmull-rom')!;
    const s = scene.apply(lecture()) as HermiteState;
    const first = construction.stepOf(s, 'patch');
    expect([0, 1, 2, 3].map((k) => caption({ ...s, step: first + k }))).toEqual([
      'Patch 1 of 4, from P₀ to P₁: the inverse matrix gives a₀ … a₃',
      'Patch 2 of 4, from P₁ to P₂: the inverse matrix gives a₀ … a₃',
      'Patch 3 of 4, from P₂ to P₃: the inverse matrix gives a₀ … a₃',
      'Patch 4 of 4, from P₃ to P₄: the inverse matrix gives a₀ … a₃',
    ]);
    // The Bézier scene's product names the data it multiplies, in the lecture's order.
    expect(caption(atBezierStep('product'))).toBe(
      'The inverse matrix times B₀, 3(B₁ − B₀), B₃, 3(B₃ − B₂) gives a₀ … a₃',
    );
  });

  it('says where the Bézier control points are as the figure shows them (B₂ is not an arrow tip)', () => {
    const s = atBezierStep('gradients');
    expect(caption(s)).toBe(
      "The end legs are a third of the gradients: B₁ is the tip of D₀'s arrow, B₂ is D₁'s tip mirrored through P₁",
    );
    for (let step = 0; step <= bezierScript.lastStep(s); step++)
      expect(caption({ ...s, step })).not.toMatch(/arrow tips|P ± D/);
    // What the caption says, read off the figure's own points: B1 is the first tip's
    // handle; B2 is the second tip mirrored through P1, which no handle is.
    const m = derive(s);
    const tips = gradientTips.handles(s).map((h) => h.position);
    expect(m.patch.bezier[1]).toEqual(tips[0]);
    const [p1, tip1, b2] = [m.patch.p1, tips[1], m.patch.bezier[2]];
    expect(b2.map((v, d) => v + tip1[d] - 2 * p1[d])).toEqual([0, 0]);
    expect(tips).not.toContainEqual(b2);
  });

  it('gives each step its formula with the numbers worked by hand', () => {
    expect(formula(atStep('gradients'))).toBe(
      "P'(\\mu) = 3a_3\\mu^2 + 2a_2\\mu + a_1,\\quad P'(0) = D_i,\\ P'(1) = D_{i+1}",
    );
    // Equation 6 with the numbers, in the lecture's order and its sums.
    expect(formula(atStep('conditions'))).toBe(
      '\\begin{aligned}P_{0} = (0.000,\\ 0.000) &= a_0\\\\ D_{0} = (3.000,\\ 4.500) &= a_1\\\\ ' +
        'P_{1} = (4.000,\\ 0.000) &= a_3 + a_2 + a_1 + a_0\\\\ D_{1} = (3.000,\\ -4.500) &= 3a_3 + 2a_2 + a_1\\end{aligned}',
    );
    // The lecture's matrix (typed from the notes) and the data P0, D0, P1, D1.
    const data =
      '\\begin{pmatrix}0.00 & 0.00\\\\3.00 & 4.50\\\\4.00 & 0.00\\\\3.00 & -4.50\\end{pmatrix}';
    expect(formula(atStep('matrix'))).toBe(
      `\\begin{pmatrix}1 & 0 & 0 & 0\\\\0 & 1 & 0 & 0\\\\1 & 1 & 1 & 1\\\\0 & 1 & 2 & 3\\end{pmatrix}${UNKNOWNS} = \\begin{pmatrix}P_{0}\\\\D_{0}\\\\P_{1}\\\\D_{1}\\end{pmatrix} = ${data}`,
    );
    // Its inverse (equation 7) times the data: a2 = −3P0 − 2D0 + 3P1 − D1 = (3, −4.5), a3 = 2P0 + D0 − 2P1 + D1 = (−2, 0).
    expect(formula(atStep('patch'))).toBe(
      `${UNKNOWNS} = \\begin{pmatrix}1 & 0 & 0 & 0\\\\0 & 1 & 0 & 0\\\\-3 & -2 & 3 & -1\\\\2 & 1 & -2 & 1\\end{pmatrix}${data} = ` +
        '\\begin{pmatrix}0.00 & 0.00\\\\3.00 & 4.50\\\\3.00 & -4.50\\\\-2.00 & 0.00\\end{pmatrix}',
    );
    // H(0.3) = (0.784, 0.216, 0.147, −0.063): P(0.3) = 0.216·(4, 0) + 0.147·(3, 4.5) − 0.063·(3, −4.5).
    expect(formula(atStep('pointAtMu'))).toBe(
      'P(0.300) = 0.784\\,P_{0} + 0.216\\,P_{1} + 0.147\\,D_{0} - 0.063\\,D_{1} = (1.116,\\ 0.945)',
    );
  });

  it('writes “Bézier is a Hermite patch” with the numbers', () => {
    // B1 = P0 + D0/3 = (1, 1.5), B2 = P1 − D1/3 = (3, 1.5).
    expect(formula(atBezierStep('bezier'))).toContain(
      'B_0 = (0.00,\\ 0.00),\\quad B_1 = (1.00,\\ 1.50),\\quad B_2 = (3.00,\\ 1.50),\\quad B_3 = (4.00,\\ 0.00)',
    );
    expect(formula(atBezierStep('gradients'))).toContain(
      "P'(1) &= 3(B_3 - B_2) = D_{1} = (3.00,\\ -4.50)",
    );
    // Equation 7 times (B0, 3(B1 − B0), B3, 3(B3 − B2)), named in the words and
    // in numbers in the formula, gives a0 … a3.
    const product = formula(atBezierStep('product'))!;
    expect(caption(atBezierStep('product'))).toContain('B₀, 3(B₁ − B₀), B₃, 3(B₃ − B₂)');
    expect(product).toMatch(
      /-3 & -2 & 3 & -1\\\\2 & 1 & -2 & 1\\end\{pmatrix\}\\begin\{pmatrix\}0\.00 & 0\.00\\\\3\.00 & 4\.50\\\\4\.00 & 0\.00\\\\3\.00 & -4\.50\\end\{pmatrix\} = \\begin\{pmatrix\}0\.00 & 0\.00\\\\3\.00 & 4\.50\\\\3\.00 & -4\.50\\\\-2\.00 & 0\.00\\end\{pmatrix\}$/,
    );
    // Equation 11 from B0 … B3 alone: a3 = B3 − 3B2 + 3B1 − B0 = (4 − 9 + 3, 0 − 4.5 + 4.5) = (−2, 0).
    expect(formula(atBezierStep('expanded'))).toContain(
      'a_3 &= B_3 - 3B_2 + 3B_1 - B_0 = (-2.000,\\ 0.000)',
    );
    // Bernstein at 0.3: (0.343, 0.441, 0.189, 0.027); the same point as the Hermite blend.
    expect(formula(atBezierStep('pointAtMu'))).toBe(
      '\\begin{aligned}P(0.300) &= 0.343\\,B_0 + 0.441\\,B_1 + 0.189\\,B_2 + 0.027\\,B_3\\\\ ' +
        '&= 0.784\\,P_{0} + 0.216\\,P_{1} + 0.147\\,D_{0} - 0.063\\,D_{1}\\\\ &= (1.116,\\ 0.945)\\end{aligned}',
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
