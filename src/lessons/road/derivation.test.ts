import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import {
  bezierToPowerBasis,
  naturalCubicCoefficients,
  naturalCubicDerivatives,
  naturalCubicSystem,
} from '../../math';
import { joinNear } from './derivation';
import { derivationFormula } from './derivationFormulas';
import { filled } from '../../render/formula';
import { derivationFocus } from './sceneDrawing';
import lesson from './lesson';
import type { RoadModel } from './model';
import { scenes } from './scenes';
import { keepShownToEnd } from './script';
import { type RoadState, SIX_VILLAGES, normalize, schema } from './state';

/** The model as the shell gets it from the kit. */
const derive = (s: RoadState) => lesson.derive(s) as RoadModel;
const steps = lesson.steps!;

/** The derivation scene as it opens, at step k. */
const opened = normalize(
  scenes.find((s) => s.id === 'derivation')!.setup(defaultsOf(schema)),
).state;
const at = (k: number, change: Partial<RoadState> = {}): RoadState =>
  normalize({ ...opened, ...change, step: k }).state;
const names = (s: RoadState) =>
  Array.from({ length: steps.count(s) + 1 }, (_, k) => derive({ ...s, step: k }).shown.name);
const formula = (s: RoadState) => steps.formula!(derive(s), s);

// The six villages (0, 0), (20, 16), (42, 10), (56, 30), (78, 26), (92, 44), worked by hand
// from the lecture slides' system (y first, as the slides do):
//   rhs y = 3(16 − 0), 3(10 − 0), 3(30 − 16), 3(26 − 10), 3(44 − 30), 3(44 − 26) = 48, 30, 42, 48, 42, 54
//   rhs x = 3·20, 3·42, 3·36, 3·36, 3·36, 3·14 = 60, 126, 108, 108, 108, 42
// Elimination gives gradients with denominator 209 (= 11·19); each row checked by substitution:
//   Dy·209 = 5084, −136, 1730, 1994, 326, 5480:
//     2·5084 − 136 = 10032 = 48·209;  5084 − 4·136 + 1730 = 6270 = 30·209;
//     −136 + 4·1730 + 1994 = 8778 = 42·209;  1730 + 4·1994 + 326 = 10032 = 48·209;
//     1994 + 4·326 + 5480 = 8778 = 42·209;  326 + 2·5480 = 11286 = 54·209.
//   Dx·209 = 3908, 4724, 3530, 3728, 4130, 2324:
//     2·3908 + 4724 = 12540 = 60·209;  3908 + 4·4724 + 3530 = 26334 = 126·209;
//     4724 + 4·3530 + 3728 = 3530 + 4·3728 + 4130 = 3728 + 4·4130 + 2324 = 22572 = 108·209;
//     4130 + 2·2324 = 8778 = 42·209.
// The matrix is strictly diagonally dominant, so these are the only solution.
const DY = [5084, -136, 1730, 1994, 326, 5480].map((v) => v / 209);
const DX = [3908, 4724, 3530, 3728, 4130, 2324].map((v) => v / 209);

// The join P2 (nearest the default p̄ = 2.4): segments 1 (P1 to P2) and 2 (P2 to P3), in y.
//   a₁ = y₁ = 16, b₁ = D₁ = −136/209,
//   c₁ = 3(10 − 16) − 2(−136/209) − 1730/209 = −18 − 1458/209 = −5220/209 ≈ −24.9761,
//   d₁ = −2(10 − 16) + (−136 + 1730)/209 = 12 + 1594/209 = 4102/209 ≈ 19.6268;
//   a₂ = 10, b₂ = 1730/209, c₂ = 3(30 − 10) − (2·1730 + 1994)/209 = 60 − 5454/209 = 7086/209 ≈ 33.9043,
//   d₂ = −2(30 − 10) + (1730 + 1994)/209 = −40 + 3724/209 = −4636/209 ≈ −22.1818.
//   y″ from the left at p = 1: 2c₁ + 6d₁ = (−10440 + 24612)/209 = 14172/209 ≈ 67.8086;
//   from the right at p = 0: 2c₂ = 14172/209: the same, as C² asks.
const SEGMENT_1 = [16, -136 / 209, -5220 / 209, 4102 / 209];
const SEGMENT_2 = [10, 1730 / 209, 7086 / 209, -4636 / 209];
const BEND = 14172 / 209;

const close = (actual: readonly number[], expected: readonly number[], digits = 12) => {
  expect(actual).toHaveLength(expected.length);
  expected.forEach((value, i) => expect(actual[i]).toBeCloseTo(value, digits));
};

describe('the derivation scene', () => {
  const m = derive(at(11));
  const work = m.derivation!;
  const [x, y] = work.coordinates;

  it('steps as the slides derive: pieces, p, a … d left and right, y″, the row, the ends, the system', () => {
    expect(names(opened)).toEqual([
      'villages',
      'pieces',
      'parameter',
      'left',
      'right',
      'second',
      'equal',
      'substitute',
      'row',
      'start',
      'end',
      'system',
    ]);
  });

  it('solves for the gradients worked by hand, as src/math does', () => {
    close(y.gradients, DY);
    close(x.gradients, DX);
    close(y.gradients, naturalCubicDerivatives(SIX_VILLAGES.map((p) => p[1])));
    close(y.rhs, [48, 30, 42, 48, 42, 54]);
    close(x.rhs, [60, 126, 108, 108, 108, 42]);
    close(y.rhs, naturalCubicSystem(SIX_VILLAGES.map((p) => p[1])).rhs);
  });

  it('works at the join nearest p̄: P₂ for p̄ = 2.4, and only ever an inner village', () => {
    expect(work.join).toBe(2);
    expect(joinNear(3.6, 5)).toBe(4);
    expect(joinNear(0.2, 5)).toBe(1);
    expect(joinNear(5, 5)).toBe(4);
    expect(joinNear(0.7, 1)).toBeNull();
  });

  it('gives a … d of the two segments at the join as worked by hand, as src/math and the drawn piece do', () => {
    close(y.pieces[1], SEGMENT_1);
    close(y.pieces[2], SEGMENT_2);
    const ys = SIX_VILLAGES.map((p) => p[1]);
    naturalCubicCoefficients(ys).forEach((piece, i) => close(y.pieces[i], piece));
    // The drawn Bézier piece, in the power basis (the segment panel's numbers), is the same cubic.
    const drawn = bezierToPowerBasis(m.visible!.pieces[1]);
    close(
      drawn.map((c) => c[1]),
      SEGMENT_1,
    );
  });

  it('has y″ equal from both sides of the join, and zero at the natural ends', () => {
    expect(y.curvature[1][1]).toBeCloseTo(BEND, 12);
    expect(y.curvature[2][0]).toBeCloseTo(BEND, 12);
    // c₀ = 48 − (2·5084 − 136)/209 = 0 and 2c₄ + 6d₄ = −108 + 22572/209 = 0.
    expect(y.curvature[0][0]).toBeCloseTo(0, 12);
    expect(y.curvature[4][1]).toBeCloseTo(0, 12);
  });

  it('writes each step’s equation with these numbers (y in the caption)', () => {
    // a and b share the first line: three lines under the words leave the map its room (#19).
    expect(formula(at(3))).toBe(
      '\\begin{aligned}a_{1} &= y_{1} = 16,\\quad b_{1} = D_{1} = -0.6507\\\\ ' +
        'c_{1} &= 3(y_{2} - y_{1}) - 2D_{1} - D_{2} = 3(10 - 16) - 2(-0.6507) - 8.2775 = -24.9761\\\\ ' +
        'd_{1} &= -2(y_{2} - y_{1}) + D_{1} + D_{2} = -2(10 - 16) + (-0.6507) + 8.2775 = 19.6268\\end{aligned}',
    );
    // Segment 2: a₂ = 10, b₂ = 1730/209 ≈ 8.2775, c₂ = 7086/209 ≈ 33.9043, d₂ = −4636/209 ≈ −22.1818.
    expect(formula(at(4))).toBe(
      '\\begin{aligned}a_{2} &= y_{2} = 10,\\quad b_{2} = D_{2} = 8.2775\\\\ ' +
        'c_{2} &= 3(y_{3} - y_{2}) - 2D_{2} - D_{3} = 3(30 - 10) - 2(8.2775) - 9.5407 = 33.9043\\\\ ' +
        'd_{2} &= -2(y_{3} - y_{2}) + D_{2} + D_{3} = -2(30 - 10) + 8.2775 + 9.5407 = -22.1818\\end{aligned}',
    );
    expect(steps.describe(at(3), 3)).toBe(
      'Segment 1, P₁ to the join P₂: a, b, c, d from heights y and gradients D at its ends',
    );
    expect(formula(at(6))).toBe(
      "y''_{1}(1) = y''_{2}(0):\\quad 2c_{1} + 6d_{1} = 2c_{2}:\\quad 67.8086 = 2(33.9043) = 67.8086",
    );
    // The row of P2: D₁ + 4D₂ + D₃ = (−136 + 6920 + 1994)/209 = 42 = 3(30 − 16), a whole
    // number written whole (the sum was printed "42.0000").
    expect(formula(at(8))).toBe(
      'D_{1} + 4D_{2} + D_{3} = 3(y_{3} - y_{1}):\\quad -0.6507 + 4(8.2775) + 9.5407 = 42 = 3(30 - 16)',
    );
    expect(formula(at(9))).toContain('2(24.3254) + (-0.6507) = 48 = 3(16 - 0)');
    expect(formula(at(10))).toContain('D_{4} + 2D_{5} = 3(y_{5} - y_{4})');
    expect(formula(at(10))).toContain('1.5598 + 2(26.2201) = 54 = 3(44 - 26)');
    // The whole system in two lines: its end rows and inner right-hand sides, then the D's.
    expect(formula(at(11))).toContain('2D_{0} + D_{1} = 48');
    expect(formula(at(11))).toContain('D_{i-1} + 4D_{i} + D_{i+1} = 30,\\ 42,\\ 48,\\ 42');
    expect(formula(at(11))).toContain('D_{4} + 2D_{5} = 54');
    expect(formula(at(11))).toContain(
      '(D_{0}, \\dots, D_{5}) = (24.3254,\\ -0.6507,\\ 8.2775,\\ 9.5407,\\ 1.5598,\\ 26.2201)',
    );
    // The panel's copy of the system: the same rows and numbers in one flowing
    // line (no aligned block), which may break after a comma as well as an =.
    const m11 = derive(at(11));
    const panel = filled(
      derivationFormula('system', m11.derivation!, 1, { pBar: 0, piece: 0, p: 0 }, true)!,
    );
    expect(panel).not.toContain('aligned');
    expect(panel).toContain('2D_{0} + D_{1} = 48,\\allowbreak\\quad ');
    expect(panel).toContain(
      'D_{i-1} + 4D_{i} + D_{i+1} = 30,\\allowbreak\\ 42,\\allowbreak\\ 48,\\allowbreak\\ 42',
    );
    expect(panel).toContain('D_{4} + 2D_{5} = 54\\ \\Rightarrow');
    expect(panel).toContain(
      '(D_{0}, \\dots, D_{5}) = (24.3254,\\allowbreak\\ -0.6507,\\allowbreak\\ 8.2775,\\allowbreak\\ 9.5407,\\allowbreak\\ 1.5598,\\allowbreak\\ 26.2201)',
    );
    expect(formula(at(2))).toBe(
      'p = \\frac{\\bar p - \\bar p_{2}}{\\bar p_{3} - \\bar p_{2}} = \\frac{2.40 - 2}{3 - 2} = 0.40',
    );
    expect(steps.describe(at(8), 8)).toBe(
      'Collect the D’s: D₁ + 4D₂ + D₃ = 3(y₃ − y₁), the row of P₂ in the system',
    );
  });

  it('moves to another join with p̄, and keeps only the ends with two villages', () => {
    const later = at(8, { pBar: 3.6 });
    expect(derive(later).derivation!.join).toBe(4);
    // Row of P4: D₃ + 4D₄ + D₅ = (1994 + 1304 + 5480)/209 = 42 = 3(44 − 30).
    expect(formula(later)).toContain('= 42 = 3(44 - 30)');
    const two = at(0, {
      villages: [
        [0, 0],
        [60, 25],
      ],
      pBar: 0.5,
    });
    expect(names(two)).toEqual(['villages', 'pieces', 'parameter', 'start', 'end', 'system']);
    // 2D₀ + D₁ = 3·25 and D₀ + 2D₁ = 3·25: D₀ = D₁ = 25, a straight road.
    expect(formula({ ...two, step: 3 })).toContain('2(25) + 25 = 75 = 3(25 - 0)');
  });

  it('keeps a derivation shown to its end at its end when a village is added', () => {
    const end = at(11);
    const added = keepShownToEnd(end, { ...end, villages: [...end.villages, [100, 50]] });
    expect(added.step).toBe(11);
    expect(keepShownToEnd(at(4), { ...at(4), villages: [...end.villages, [100, 50]] }).step).toBe(
      4,
    );
  });

  it('marks the segments and the villages the step talks about on the map', () => {
    const focus = (k: number, change: Partial<RoadState> = {}) =>
      derivationFocus(derive(at(k, change)));
    expect(focus(0)).toEqual({ pieces: [], villages: [] });
    // The marker's segment while p is explained; then the join P2 and its two segments.
    expect(focus(2)).toEqual({ pieces: [2], villages: [] });
    expect(focus(3)).toEqual({ pieces: [1], villages: [2] });
    expect(focus(4)).toEqual({ pieces: [2], villages: [2] });
    expect(focus(6)).toEqual({ pieces: [1, 2], villages: [2] });
    expect(focus(8)).toEqual({ pieces: [1, 2], villages: [1, 2, 3] });
    expect(focus(9)).toEqual({ pieces: [0], villages: [0] });
    expect(focus(10)).toEqual({ pieces: [4], villages: [5] });
    expect(focus(8, { pBar: 3.6 })).toEqual({ pieces: [3, 4], villages: [3, 4, 5] });
  });
});
