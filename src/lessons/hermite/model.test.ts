import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { checkScript } from '../../kit/scriptChecks';
import { plottedBasis } from './basisFigure';
import lesson from './lesson';
import type { HermiteModel } from './model';
import { type HermiteState, normalize, schema } from './state';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: HermiteState) => lesson.derive(s) as HermiteModel;
const stepCount = (s: HermiteState) => lesson.steps!.count(s);
const stepFormula = (m: HermiteModel, s: HermiteState) => lesson.steps!.formula!(m, s);
/** What step `step` shows, in the words of the lecture's construction. */
const revealed = (s: HermiteState) => {
  const { shown } = derive(s);
  return {
    gradients: shown.has('gradients'),
    basis: plottedBasis(shown),
    patches: shown.count('patch'),
    building: shown.is('patch') ? shown.index - 1 : null,
    point: shown.has('pointAtMu'),
    bezier: shown.has('bezier'),
  };
};

// Values worked out by hand from the four conditions P(0) = Pi, P(1) = Pi+1, P′(0) = Di, P′(1) = Di+1:
// a0 = Pi, a1 = Di, a2 = 3(Pi+1 − Pi) − 2Di − Di+1, a3 = 2(Pi − Pi+1) + Di + Di+1.

const lecture: HermiteState = defaultsOf(schema); // P0 = (0, 0), P1 = (4, 0), D0 = (3, 4.5), D1 = (3, −4.5)
const several: HermiteState = {
  ...lecture,
  points: [
    [0, 0],
    [2, 2],
    [5, 1.5],
    [6.5, -1],
    [9, 0.5],
  ],
  handGradients: [
    [2, 3],
    [3, 0],
    [2, -2],
    [3, 0],
    [2, 2],
  ],
  mode: 'catmull-rom',
  patch: 1,
};

const close = (actual: readonly (readonly number[])[], expected: readonly (readonly number[])[]) =>
  expected.forEach((row, i) => row.forEach((v, d) => expect(actual[i][d]).toBeCloseTo(v, 12)));

describe('derive (Hermite)', () => {
  it('solves the four conditions for the lecture patch', () => {
    const m = derive(lecture);
    close(m.patch.coefficients, [
      [0, 0],
      [3, 4.5],
      [3, -4.5],
      [-2, 0],
    ]);
    expect(m.m).toBe(1);
    expect(m.joins).toEqual([]);
  });

  it('puts the arrow tips at P + D/3, the inner Bézier control points', () => {
    const m = derive(lecture);
    close(m.tips, [
      [1, 1.5],
      [5, -1.5],
    ]);
    close(m.patch.bezier, [
      [0, 0],
      [1, 1.5],
      [3, 1.5],
      [4, 0],
    ]);
    expect(m.patch.bezier).toBe(m.segments[0]);
  });

  it('blends P(½) = ½P0 + ½P1 + ⅛D0 − ⅛D1 = (2, 1.125)', () => {
    const m = derive({ ...lecture, mu: 0.5 });
    close([m.patch.weights], [[0.5, 0.5, 0.125, -0.125]]);
    close([m.patch.point], [[2, 1.125]]);
  });

  it('takes Catmull-Rom gradients from the neighbours, zero at the ends, C¹ at every join', () => {
    const m = derive(several);
    // Dk = (Pk+1 − Pk−1) / 2, e.g. D2 = ((6.5 − 2) / 2, (−1 − 2) / 2), D3 = ((9 − 5) / 2, (0.5 − 1.5) / 2).
    close(m.gradients, [
      [0, 0],
      [2.5, 0.75],
      [2.25, -1.5],
      [2, -0.5],
      [0, 0],
    ]);
    expect(m.patch.p0).toEqual([2, 2]);
    expect(m.joins.map((j) => j.k)).toEqual([1, 2, 3]);
    for (const join of m.joins) {
      expect(['C1', 'C2']).toContain(join.continuity);
      // A cubic Bézier leaves with 3(B1 − B0) = Di: P′ on both sides is the shared gradient.
      close([join.before, join.after], [m.gradients[join.k], m.gradients[join.k]]);
    }
  });

  it('says why two points in Catmull-Rom mode make a straight segment', () => {
    const m = derive({ ...lecture, mode: 'catmull-rom' });
    expect(m.straight).toBe(true);
    expect(m.note).toMatch(/^Two points have no neighbours/);
    // a2 = 3(P1 − P0) with both gradients zero.
    close([m.patch.coefficients[2]], [[12, 0]]);
  });

  it('says why a patch whose points and gradients are all at one spot is a point', () => {
    const m = derive({
      ...lecture,
      points: [
        [1, 1],
        [1, 1],
      ],
      handGradients: [
        [0, 0],
        [0, 0],
      ],
    });
    expect(m.note).toMatch(/^P0 and P1 are at one spot/);
    expect(derive(lecture).note).toBeNull();
  });

  it('fits points, curve and tips', () => {
    expect(derive(lecture).bounds).toEqual({ minX: 0, minY: -1.5, maxX: 5, maxY: 1.5 });
  });

  it('fits the loop of long gradients with both arrows, whose tips are handles', () => {
    // D0 = (15, 12), D1 = (15, −12): tips at (5, 4) and (9, −4). The curve is
    // the Bézier (0, 0), (5, 4), (−1, 4), (4, 0), between y = 0 and y(½) = 3.
    const m = derive({
      ...lecture,
      handGradients: [
        [15, 12],
        [15, -12],
      ],
    });
    expect(m.bounds).toEqual({ minX: 0, minY: -4, maxX: 9, maxY: 4 });
    // The Bézier view fits its control point B2 = (−1, 4) too.
    expect(derive({ ...m.state, bezier: true }).bounds.minX).toBe(-1);
  });

  it('keeps a valid patch and says when it cannot', () => {
    const fixed = normalize({
      ...several,
      points: lecture.points,
      handGradients: lecture.handGradients,
      patch: 2,
    });
    expect(fixed.state.patch).toBe(0);
    expect(fixed.issues.join(' ')).toMatch(/^patch: there is no patch 3 among 1/);
    expect(normalize(several).issues).toEqual([]);
  });

  it('says what points on one spot or on one line do', () => {
    expect(
      derive({
        ...lecture,
        points: [
          [0, 0],
          [1, 1],
          [3, 3],
        ],
        handGradients: [
          [1, 0],
          [1, 0],
          [1, 0],
        ],
      }).note,
    ).toMatch(/^The points lie on one line: the patches stay on it only/);
    expect(
      derive({
        ...lecture,
        points: [
          [0, 0],
          [0, 0],
        ],
      }).note,
    ).toMatch(/^All points are on one spot/);
  });
});

describe('the script (Hermite)', () => {
  it('every scene steps from the points to the whole construction, drawing more at the end', () => {
    checkScript(lesson);
  });

  it('points, gradients, the conditions, the matrix, each patch solved in turn, H0 H1, H2 H3, then P(μ)', () => {
    const five = { ...several, mode: 'hand' as const };
    expect(stepCount(five)).toBe(7 + 3);
    expect(revealed({ ...five, step: 1 })).toMatchObject({ gradients: true, basis: 0, patches: 0 });
    expect(revealed({ ...five, step: 3 })).toMatchObject({ basis: 0, patches: 0, building: null });
    expect(revealed({ ...five, step: 6 })).toMatchObject({ patches: 3, building: 2, basis: 0 });
    expect(revealed({ ...five, step: 9 })).toMatchObject({ patches: 4, basis: 4, point: false });
    expect(revealed({ ...five, step: 10 })).toMatchObject({
      patches: 4,
      building: null,
      point: true,
    });
    // Before the patches are solved, the conditions are the chosen patch's (P1 to P2).
    expect(derive({ ...five, step: 2 }).patch.index).toBe(1);
    // While patch 3 (index 2) is solved, the matrix is about it: a0 = P2, a1 = D2.
    const m = derive({ ...five, step: 6 });
    expect(m.patch.index).toBe(2);
    close(m.patch.coefficients.slice(0, 2), [
      [5, 1.5],
      [2, -2],
    ]);
    expect(derive({ ...five, step: 10 }).patch.index).toBe(1);
    // The Bézier view walks its own seven steps, for one patch or several.
    expect(stepCount({ ...lecture, bezier: true })).toBe(6);
    expect(stepCount({ ...five, bezier: true })).toBe(6);
  });

  it('writes P(μ) with the signs in the formula, never "+ −"', () => {
    const m = derive({ ...lecture, mu: 0.5, step: 7 });
    const tex = stepFormula(m, m.state)!;
    expect(tex).not.toMatch(/\+\s*-/);
    expect(tex).toMatch(/0\.125\\,D_\{0\} - 0\.125\\,D_\{1\}/);
  });
});
