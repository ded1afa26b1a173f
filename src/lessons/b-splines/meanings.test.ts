import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { drawState } from '../../kit/scriptChecks';
import { type Point, nurbsPoint } from '../../math';
import { knotFigure } from './knotFigure';
import lesson from './lesson';
import type { BSplineModel, MeaningsModel } from './model';
import { KNOT_WORDS, NOTES_SYMBOLS } from './notes';
import { SCENES } from './scenes';
import { type BSplineState, SEVEN_POINTS, normalize, schema } from './state';
import { TEXTS } from './texts';

const defaults = normalize(defaultsOf(schema)).state;
const scene = normalize(SCENES.find((s) => s.id === 'meanings')!.setup(defaults)).state;
const steps = lesson.steps!;
const NAMES = ['points', 'values', 'joins', 'lecture', 'controls', 'meet'] as const;
const stepOf = (name: (typeof NAMES)[number]) => NAMES.indexOf(name);
function model(state: BSplineState = scene, step = NAMES.length - 1): MeaningsModel {
  const m = lesson.derive({ ...state, step }) as BSplineModel;
  if (m.kind !== 'meanings') throw new Error(`a ${m.kind} model`);
  return m;
}
const caption = (name: (typeof NAMES)[number], state: BSplineState = scene) =>
  steps.describe({ ...state, step: stepOf(name) }, stepOf(name));
const gap = (a: readonly number[], b: readonly number[]) =>
  Math.max(...a.map((v, d) => Math.abs(v - b[d])));
const ones = SEVEN_POINTS.map(() => 1);

describe('two meanings of “knots” on one curve', () => {
  it('steps from the points to the values, their curve points, each document’s knots, and where they meet', () => {
    const names = NAMES.map((_, k) => model(scene, k).shown.name);
    expect(names).toEqual([...NAMES]);
    expect(steps.count(scene)).toBe(NAMES.length - 1);
  });

  it('the knot values in the curve and P(u) at each: clamped, by hand and by the maths', () => {
    // Clamped knots 0,0,0,0, ¼, ½, ¾, 1,1,1,1 on the seven points. At a simple knot uj the
    // cubic is N(j−3) P(j−3) + N(j−2) P(j−2) + N(j−1) P(j−1) with N(j−3) = (u(j+1) − uj)²/
    // ((u(j+1) − u(j−2))(u(j+1) − u(j−1))), N(j−1) = (uj − u(j−1))²/((u(j+2) − u(j−1))(u(j+1) − u(j−1))):
    // u4 = ¼: ¼ P1 + 7/12 P2 + 1/6 P3 = (2.75, 3.25); u5 = ½: (P2 + 4P3 + P4)/6;
    // u6 = ¾: 1/6 P3 + 7/12 P4 + ¼ P5; the clamped ends are P0 and P6.
    const byHand: [number, number, Point, number | null][] = [
      [0, 3, [0, 0], 0],
      [0.25, 4, [2.75, 3.25], null],
      [0.5, 5, [27.5 / 6, 8 / 6], null],
      [0.75, 6, [4.5 / 6 + (7 / 12) * 6.5 + 2, 1 / 6 + 0.75], null],
      [1, 7, [10, 3.5], 6],
    ];
    const { knotPoints, knots } = model();
    expect(knotPoints.map((k) => [k.u, k.index, k.on])).toEqual(
      byHand.map(([u, index, , on]) => [u, index, on]),
    );
    knotPoints.forEach((k, i) => {
      expect(gap(k.at, byHand[i][2]), `P(u${k.index})`).toBeLessThan(1e-12);
      expect(gap(k.at, nurbsPoint(SEVEN_POINTS, ones, knots, 3, k.u))).toBe(0);
    });
    expect(knotPoints.map((k) => k.multiplicity)).toEqual([4, 1, 1, 1, 4]);
  });

  it('writes each knot value and its curve point as a two-row table, by hand (#19)', () => {
    // The clamped points above: u3 = 0 at P0, u4 = ¼ at (2.75, 3.25), u5 = ½ at (27.5/6, 8/6) =
    // (4.58, 1.33), u6 = ¾ at (6.5417, 0.9167) = (6.54, 0.92), u7 = 1 at P6 = (10, 3.5).
    const joins = { ...scene, step: stepOf('joins') };
    expect(steps.formula!(lesson.derive(joins), joins)).toBe(
      '\\begin{array}{r|ccccc} u & u_{3} = 0 & u_{4} = 0.25 & u_{5} = 0.5 & u_{6} = 0.75 & u_{7} = 1 \\\\ \\hline ' +
        'P(u) & (0.00,\\ 0.00) & (2.75,\\ 3.25) & (4.58,\\ 1.33) & (6.54,\\ 0.92) & (10.00,\\ 3.50)\\end{array}',
    );
    // Ten points on knots 0 … 13: u3 … u10, eight of them: the first three, ⋯, the last two.
    const ten = normalize({
      ...scene,
      points: Array.from({ length: 10 }, (_, i): Point => [i, i % 2]),
      knots: Array.from({ length: 14 }, (_, j) => j),
      weights: Array.from({ length: 10 }, () => 1),
      step: stepOf('joins'),
    }).state;
    const many = steps.formula!(lesson.derive(ten), ten)!;
    expect(many).toMatch(
      /^\\begin\{array\}\{r\|cccccc\} u & u_\{3\} = 3 & u_\{4\} = 4 & u_\{5\} = 5 & \\cdots & u_\{9\} = 9 & u_\{10\} = 10 \\\\/,
    );
    expect(steps.describe(ten, stepOf('joins'))).toContain('P(u₃) … P(u₁₀)');
  });

  it('unclamped knots 0 … 10: only u3 … u7 have curve points, and none is a control point', () => {
    const knots = Array.from({ length: 11 }, (_, j) => j);
    const state = normalize({ ...scene, knots }).state;
    // On knots 1 apart P(uj) = (P(j−3) + 4P(j−2) + P(j−1))/6.
    const byHand: Point[] = [
      [7 / 6, 16 / 6],
      [17.5 / 6, 20 / 6],
      [27.5 / 6, 8 / 6],
      [38.5 / 6, 4 / 6],
      [48.5 / 6, 15.5 / 6],
    ];
    const { knotPoints } = model(state);
    expect(knotPoints.map((k) => k.index)).toEqual([3, 4, 5, 6, 7]);
    knotPoints.forEach((k, i) => {
      expect(gap(k.at, byHand[i])).toBeLessThan(1e-12);
      expect(gap(k.at, nurbsPoint(SEVEN_POINTS, ones, knots, 3, k.u))).toBe(0);
    });
    expect(knotPoints.every((k) => k.on === null)).toBe(true);
    // The nearest pair: P(u5) and P3 = (4.5, 1), (1/12, 1/3) apart: √17/12 = 0.344.
    expect(caption('meet', state)).toBe(
      'No curve point at a knot lands on a control point here: the nearest pair, P(u₅) and P₃, is marked with its distance',
    );
    const last = { ...state, step: stepOf('meet') };
    expect(steps.formula!(lesson.derive(last), last)).toBe(
      '\\text{nearest: } \\lvert P(u_{5}) - P_{3} \\rvert = 0.344',
    );
    expect(Math.sqrt(17) / 12).toBeCloseTo(0.344, 3);
  });

  it('where knots make a join a control point, the two meanings are one spot', () => {
    expect(caption('meet')).toBe(
      'Both meanings on one spot: P(u₃) = P₀ and P(u₇) = P₆, where the curve’s point at a knot value is a control point',
    );
    // The repeated scene's knots: a knot of multiplicity p = 3 at u = 1 puts P(1) on P3.
    const repeated = normalize({ ...scene, knots: [0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2] }).state;
    expect(model(repeated).knotPoints.map((k) => k.on)).toEqual([0, 3, 6]);
    expect(caption('meet', repeated)).toMatch(/P\(u₃\) = P₀, P\(u₄\) = P₃ and P\(u₇\) = P₆/);
  });

  it('quotes each document as it uses the word', () => {
    expect(caption('values')).toBe(
      'Knots in the continuation notes and here: the parameter values u0 ≤ … ≤ u10 on the strip; the curve P(u) runs over them',
    );
    expect(caption('joins')).toBe(
      'At the knot values the curve’s pieces join: P(u₃) … P(u₇), each named after its u on the strip',
    );
    expect(caption('lecture')).toContain(`“${KNOT_WORDS.lectureJoin}”`);
    expect(caption('controls')).toContain(`“${KNOT_WORDS.splineSlides}”`);
    expect(caption('controls')).toContain(`“${KNOT_WORDS.lectureBezier}”`);
    for (const words of Object.values(KNOT_WORDS))
      expect(TEXTS.meanings.text).toContain(`“${words}”`);
    expect(TEXTS.meanings.text).toMatch(/lecture slides do not use the word/);
    // The key it shows: the row that says it in words stays.
    expect(NOTES_SYMBOLS.map(([here]) => here)).toContain(
      'knots u0 ≤ u1 ≤ …: parameter values where segments meet',
    );
  });

  it('draws each P(uj) named on the curve, a tick at its u on the strip, then each meaning’s rings', () => {
    const curve = (step: number) =>
      drawState({ ...lesson, figures: [lesson.figures[0]] }, { ...scene, step });
    const strip = (step: number) =>
      drawState({ ...lesson, figures: [knotFigure] }, { ...scene, step }).elements;
    const joins = curve(stepOf('joins')).texts.join('');
    for (const j of [3, 4, 5, 6, 7]) expect(joins).toContain(`P(u${j})`);
    expect(curve(stepOf('values')).texts.join('')).not.toContain('P(u3)');
    expect(strip(stepOf('joins')) - strip(stepOf('values'))).toBe(5);
    expect(curve(stepOf('lecture')).texts.join('')).toContain('the lecture notes’ knots');
    expect(curve(stepOf('controls')).texts.join('')).toContain('the “Splines” slides’ knots');
    // The last step rings the two spots where the meanings meet.
    expect(curve(stepOf('meet')).elements - curve(stepOf('controls')).elements).toBe(2);
  });
});
