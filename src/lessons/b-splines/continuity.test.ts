import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { drawState } from '../../kit/scriptChecks';
import {
  type Point,
  bezierDerivative,
  bezierJointContinuity,
  nurbsPoint,
  uniformBSplineSegments,
} from '../../math';
import {
  AGREE,
  CONTINUITY_CASES,
  type ContinuityCase,
  caseKnots,
  continuityCurves,
  pieceDerivatives,
  watchedKnot,
} from './continuityGeometry';
import lesson from './lesson';
import type { BSplineModel, ContinuityModel } from './model';
import { controlPoints } from './points';
import { SCENES } from './scenes';
import { type BSplineState, SEVEN_POINTS, normalize, schema } from './state';
import { TEXTS } from './texts';

const defaults = normalize(defaultsOf(schema)).state;
const scene = normalize(SCENES.find((s) => s.id === 'continuity')!.setup(defaults)).state;
const steps = lesson.steps!;
/** The continuity model at the step that shows `name`. */
function at(name: ContinuityCase, state: BSplineState = scene): ContinuityModel {
  const step = CONTINUITY_CASES.indexOf(name) + 1;
  const m = lesson.derive({ ...state, step }) as BSplineModel;
  if (m.kind !== 'continuity') throw new Error(`a ${m.kind} model`);
  return m;
}
/** What the curve figure alone draws. */
const drawCurve = (s: BSplineState) => drawState({ ...lesson, figures: [lesson.figures[0]] }, s);
const gap = (a: readonly number[], b: readonly number[]) =>
  Math.max(...a.map((v, d) => Math.abs(v - b[d])));
/** Relative to the vectors' size, as the model counts two sides equal. */
const relativeGap = (a: readonly number[], b: readonly number[]) =>
  gap(a, b) / Math.max(1, ...a.map(Math.abs), ...b.map(Math.abs));

// The seven points: P0 (0,0), P1 (1,3), P2 (3,4), P3 (4.5,1), P4 (6.5,0), P5 (8,3), P6 (10,3.5).
// Worked by hand at the watched knot u = 5 (m + 1 = 7: ⌊(7 + 3)/2⌋ = 5), knots 1 apart:
const HAND: Record<ContinuityCase, { smooth: number; left: Point[]; right: Point[] }> = {
  // Degree 1 is the polygon: P(5) = P4; P′ is P4 − P3 before, P5 − P4 after.
  linear: {
    smooth: 0,
    left: [
      [6.5, 0],
      [2, -1],
    ],
    right: [
      [6.5, 0],
      [1.5, 3],
    ],
  },
  // Degree 2, span [j, j+1) on P(j−2), P(j−1), Pj: P(5) = (P3 + P4)/2, P′ = P4 − P3 both sides,
  // P″ = P2 − 2P3 + P4 before, P3 − 2P4 + P5 after.
  quadratic: {
    smooth: 1,
    left: [
      [5.5, 0.5],
      [2, -1],
      [0.5, 2],
    ],
    right: [
      [5.5, 0.5],
      [2, -1],
      [-0.5, 4],
    ],
  },
  // Degree 3: P(5) = (P2 + 4P3 + P4)/6, P′ = (P4 − P2)/2, P″ = P2 − 2P3 + P4 both sides;
  // P‴ = −P1 + 3P2 − 3P3 + P4 before, −P2 + 3P3 − 3P4 + P5 after.
  cubic: {
    smooth: 2,
    left: [
      [27.5 / 6, 8 / 6],
      [1.75, -2],
      [0.5, 2],
      [1, 6],
    ],
    right: [
      [27.5 / 6, 8 / 6],
      [1.75, -2],
      [0.5, 2],
      [-1, 2],
    ],
  },
  // Knots 0 1 2 3 4 5 5 7 8 9 10. By blossoms P3 = f(4,5,5), P4 = f(5,5,7): P(5) = f(5,5,5)
  // = (2P3 + P4)/3. P′ is the quadratic B-spline of Qi = 3(P(i+1) − Pi)/(u(i+4) − u(i+1)):
  // Q3 = 3(P4 − P3)/3 = (2, −1), where its own double knot puts it, both sides. P″: the
  // linear B-spline of Ri = 2(Q(i+1) − Qi)/(u(i+4) − u(i+2)), with Q2 = 3(P3 − P2)/2 = (2.25, −4.5),
  // Q4 = 3(P5 − P4)/3 = (1.5, 3): R2 = 2(Q3 − Q2)/1 = (−0.5, 7) before, R3 = 2(Q4 − Q3)/2 = (−0.5, 4) after.
  double: {
    smooth: 1,
    left: [
      [15.5 / 3, 2 / 3],
      [2, -1],
      [-0.5, 7],
    ],
    right: [
      [15.5 / 3, 2 / 3],
      [2, -1],
      [-0.5, 4],
    ],
  },
  // Knots 0 1 2 3 5 5 5 7 8 9 10: only N(3,3) is 1 at u = 5, so P(5) = P3 = (4.5, 1). P′ jumps
  // from Q2 = 3(P3 − P2)/(u6 − u3) = (2.25, −4.5) to Q3 = 3(P4 − P3)/(u7 − u4) = (3, −1.5).
  triple: {
    smooth: 0,
    left: [
      [4.5, 1],
      [2.25, -4.5],
    ],
    right: [
      [4.5, 1],
      [3, -1.5],
    ],
  },
};

describe('derivatives of a piece at its ends', () => {
  it('are the polynomial’s own: u³ − 2u and 5u² + 1 on [1, 3]', () => {
    const at = (u: number): Point => [u ** 3 - 2 * u, 5 * u * u + 1];
    // At 1: (−1, 6), (1, 10), (6, 10), (6, 0). At 3: (21, 46), (25, 30), (18, 10), (6, 0).
    const start = pieceDerivatives(at, 1, 3, 1, 3);
    const end = pieceDerivatives(at, 1, 3, 3, 3);
    const byHand = [
      [
        [-1, 6],
        [1, 10],
        [6, 10],
        [6, 0],
      ],
      [
        [21, 46],
        [25, 30],
        [18, 10],
        [6, 0],
      ],
    ];
    [start, end].forEach((found, side) =>
      found.forEach((d, r) =>
        expect(gap(d, byHand[side][r]), `side ${side}, r ${r}`).toBeLessThan(1e-9),
      ),
    );
  });

  it('read the piece alone: nothing of the neighbour across a knot', () => {
    // The triple knot's curve turns at P3; each side's P′ is its own piece's.
    const m = at('triple');
    expect(gap(m.watched.left[1], HAND.triple.left[1])).toBeLessThan(1e-9);
    expect(gap(m.watched.right[1], HAND.triple.right[1])).toBeLessThan(1e-9);
  });
});

describe('degree p ⇒ Cᵖ⁻¹, and a knot of multiplicity k ⇒ Cᵖ⁻ᵏ, on the seven points', () => {
  it('each step’s degree and knots', () => {
    expect(watchedKnot(7)).toBe(5);
    const range = (n: number) => Array.from({ length: n }, (_, j) => j);
    expect(caseKnots(7, 'linear')).toEqual({ degree: 1, knots: range(9) });
    expect(caseKnots(7, 'quadratic')).toEqual({ degree: 2, knots: range(10) });
    expect(caseKnots(7, 'cubic')).toEqual({ degree: 3, knots: range(11) });
    expect(caseKnots(7, 'double').knots).toEqual([0, 1, 2, 3, 4, 5, 5, 7, 8, 9, 10]);
    expect(caseKnots(7, 'triple').knots).toEqual([0, 1, 2, 3, 5, 5, 5, 7, 8, 9, 10]);
    for (const name of CONTINUITY_CASES) {
      const m = at(name);
      expect([m.degree, m.knots]).toEqual([caseKnots(7, name).degree, caseKnots(7, name).knots]);
    }
  });

  for (const name of CONTINUITY_CASES) {
    it(`${name}: left and right agree to ${AGREE} up to C^k and differ at k + 1, as worked by hand`, () => {
      const { watched: w, degree } = at(name);
      const hand = HAND[name];
      expect(w.u).toBe(5);
      expect(w.smooth).toBe(hand.smooth);
      expect(w.smooth).toBe(w.promised);
      hand.left.forEach((v, r) => expect(gap(w.left[r], v), `left ${r}`).toBeLessThan(1e-9));
      hand.right.forEach((v, r) => expect(gap(w.right[r], v), `right ${r}`).toBeLessThan(1e-9));
      for (let r = 0; r <= hand.smooth; r++)
        expect(relativeGap(w.left[r], w.right[r]), `r = ${r}`).toBeLessThan(AGREE);
      expect(relativeGap(w.left[hand.smooth + 1], w.right[hand.smooth + 1])).toBeGreaterThan(0.1);
      // The point is the maths' own P(5).
      const { knots } = caseKnots(7, name);
      const ones = SEVEN_POINTS.map(() => 1);
      expect(gap(w.left[0], nurbsPoint(SEVEN_POINTS, ones, knots, degree, 5))).toBeLessThan(1e-12);
    });
  }

  it('the cubic agrees with the maths’ Bézier pieces and their joint verdict: C²', () => {
    // On knots 1 apart the piece on [j, j+1) is Q(j) of the matrix form, local t = u − j.
    const beziers = uniformBSplineSegments(SEVEN_POINTS);
    const [before, after] = [beziers[1], beziers[2]];
    expect(bezierJointContinuity(before, after)).toBe('C2');
    const w = at('cubic').watched;
    let [left, right] = [before, after];
    for (let r = 0; r <= 3; r++) {
      expect(gap(w.left[r], left[left.length - 1]), `left ${r}`).toBeLessThan(1e-9);
      expect(gap(w.right[r], right[0]), `right ${r}`).toBeLessThan(1e-9);
      [left, right] = [bezierDerivative(left), bezierDerivative(right)];
    }
  });

  it('every knot of every step is as continuous as its multiplicity says, and only that', () => {
    for (const name of CONTINUITY_CASES) {
      for (const check of at(name).checks) {
        expect(check.smooth, `${name} at ${check.u}`).toBe(check.promised);
        expect(check.promised).toBe(caseKnots(7, name).degree - check.multiplicity);
      }
    }
  });

  it('for any points: derivatives agree up to Cᵖ⁻ᵏ at every knot', () => {
    const point = fc.tuple(
      fc.double({ min: -10, max: 10, noNaN: true }),
      fc.double({ min: -10, max: 10, noNaN: true }),
    );
    fc.assert(
      fc.property(fc.array(point, { minLength: 7, maxLength: 9 }), (points) => {
        const curves = continuityCurves({ ...scene, points });
        return CONTINUITY_CASES.every((name) =>
          curves[name].checks.every(
            (check) =>
              check.smooth >= check.promised &&
              check.agree.slice(0, check.promised + 1).every(Boolean),
          ),
        );
      }),
      { numRuns: 60 },
    );
  });
});

describe('the continuity scene', () => {
  it('steps through the points, degree 1, 2, 3, a double and a triple knot', () => {
    const names = Array.from({ length: steps.count(scene) + 1 }, (_, k) => {
      const m = lesson.derive({ ...scene, step: k }) as BSplineModel;
      return m.shown.name;
    });
    expect(names).toEqual(['points', ...CONTINUITY_CASES]);
  });

  it('says at each step what the numbers show', () => {
    const caption = (name: ContinuityCase) => {
      const k = CONTINUITY_CASES.indexOf(name) + 1;
      return steps.describe({ ...scene, step: k }, k);
    };
    expect(caption('linear')).toBe(
      'Degree 1 on simple knots, at u = 5: P matches left and right, P′ does not: C⁰ = C¹⁻¹, through P₄',
    );
    expect(caption('quadratic')).toBe(
      'Degree 2 on simple knots, at u = 5: P and P′ match left and right, P″ does not: C¹ = C²⁻¹',
    );
    expect(caption('cubic')).toBe(
      'Degree 3 on simple knots, at u = 5: P, P′ and P″ match left and right, P‴ does not: C² = C³⁻¹',
    );
    expect(caption('double')).toBe(
      'A double knot at u = 5 (u₆ moved onto u₅): P and P′ match left and right, P″ does not: C¹ = C³⁻²',
    );
    expect(caption('triple')).toBe(
      'A triple knot at u = 5 (u₄ and u₆ moved onto u₅): P matches left and right, P′ does not: C⁰ = C³⁻³, through P₃',
    );
  });

  it('its formula writes both sides of every derivative, = or ≠, and the verdict', () => {
    const k = CONTINUITY_CASES.indexOf('cubic') + 1;
    const state = { ...scene, step: k };
    const tex = steps.formula!(lesson.derive(state), state)!;
    // A column per derivative: P, P′ and P″ agree, P‴ does not; the left and right values in rows.
    expect(tex).toContain(
      "P(5^-) = P(5^+) & P'(5^-) = P'(5^+) & P''(5^-) = P''(5^+) & P'''(5^-) \\ne P'''(5^+)",
    );
    expect(tex).toMatch(
      /u \\to 5\^- & [^\\]*\\ [^&]*& [^&]*& \(0\.50,\\ 2\.00\) & \(1\.00,\\ 6\.00\)/,
    );
    expect(tex).toMatch(/u \\to 5\^\+ & .*\(0\.50,\\ 2\.00\) & \(-1\.00,\\ 2\.00\)\\end/);
    expect(tex).toMatch(/\\Rightarrow\\; C\^\{2\}$/);
  });

  it('draws the first derivative that breaks, left and right, and each knot’s Cᵏ', () => {
    const k = CONTINUITY_CASES.indexOf('cubic') + 1;
    const { texts } = drawCurve({ ...scene, step: k });
    expect(texts.filter((t) => t === 'C²')).toHaveLength(3);
    expect(texts).toContain('P‴(5⁻)');
    expect(texts).toContain('P‴(5⁺)');
    // Step 0: the points alone (their handles are the shell's), no label of the figure's.
    expect(drawCurve(scene).texts).toEqual([]);
  });

  it('keeps seven points: fewer cannot hold a triple knot inside a cubic', () => {
    expect(controlPoints.remove(scene, 0)).toBeNull();
    const eight = { ...scene, points: [...scene.points, [11, 0]] };
    expect(controlPoints.remove(normalize(eight).state, 0)).not.toBeNull();
    const { state, issues } = normalize({ ...scene, points: scene.points.slice(0, 5) });
    expect(state.points).toEqual(SEVEN_POINTS);
    expect(issues[0]).toMatch(/at least 7 control points, not 5/);
    // Elsewhere five points stay.
    expect(normalize({ ...defaults, points: scene.points.slice(0, 5) }).state.points).toHaveLength(
      5,
    );
  });

  it('says where the notes say it, and how the two sides are compared', () => {
    const { text } = TEXTS.continuity;
    expect(text).toContain('“cubic B-splines are C², or can be made to be less: C¹ or C⁰”');
    expect(text).toContain('“splines of degree n can guarantee Cⁿ⁻¹ continuity”');
    expect(text).toContain(
      '“three control points are on a straight line, and the distance is the same”',
    );
    expect(text).toContain(`within ${AGREE}`);
  });
});
