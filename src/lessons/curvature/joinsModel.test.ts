import { describe, expect, it } from 'vitest';
import { normalizeState } from '../../app/lessonState';
import { defaultsOf } from '../../app/urlState';
import {
  type Point,
  bezierCurvature,
  bezierDerivative,
  bezierTangent,
  catmullRomSegments,
  cubicSplineC2,
  norm,
} from '../../math';
import { SLOPE_STEP, curvatureSlope } from './curvatureSlope';
import { drawState } from '../../kit/scriptChecks';
import { catmullJoinName, naturalJoinName } from './joinsMarks';
import lesson from './lesson';
import type { CurvatureModel } from './model';
import { type CurvatureState, schema } from './state';

const defaults = defaultsOf(schema) as CurvatureState;
const derive = (s: CurvatureState) => lesson.derive(s) as CurvatureModel;
const opened = (step = 0) => ({
  ...(lesson.scenes!.find((s) => s.id === 'joins')!.apply(defaults) as CurvatureState),
  step,
});

/**
 * dκ/dp from src/math's derivatives, the quotient rule on κ = (x′y″ − y′x″)/|P′|³:
 * dκ/dp = (x′y‴ − y′x‴)/|P′|³ − 3(x′y″ − y′x″)(P′·P″)/|P′|⁵, and dκ/ds = (dκ/dp)/|P′|.
 */
function analyticSlope(piece: readonly Point[], p: number): number {
  const h1 = bezierDerivative(piece);
  const h2 = bezierDerivative(h1);
  const [d1, d2, d3] = [
    bezierTangent(piece, p),
    bezierTangent(h1, p),
    h2[1].map((v, i) => v - h2[0][i]),
  ];
  const speed = norm(d1);
  const cross = d1[0] * d2[1] - d1[1] * d2[0];
  const along = d1[0] * d2[0] + d1[1] * d2[1];
  const perParameter =
    (d1[0] * d3[1] - d1[1] * d3[0]) / speed ** 3 - (3 * cross * along) / speed ** 5;
  return perParameter / speed;
}

describe('dκ/ds by finite differences of src/math’s κ', () => {
  it('matches the slope of (t, t³) worked by hand at both ends', () => {
    // (t, t³) is the Bézier curve (0, 0), (1/3, 0), (2/3, 0), (1, 1). κ = 6t/(1 + 9t⁴)^{3/2}.
    // At t = 0: dκ/dt = 6 and |P′| = 1, so dκ/ds = 6.
    // At t = 1: dκ/dt = [6·10^{3/2} − 6·(3/2)·10^{1/2}·36] / 10³ = 10^{1/2}(60 − 324)/1000,
    // and |P′| = √10, so dκ/ds = −264/1000 = −0.264.
    const cubic = [
      [0, 0],
      [1 / 3, 0],
      [2 / 3, 0],
      [1, 1],
    ];
    expect(curvatureSlope(cubic, 0)!.perLength).toBeCloseTo(6, 6);
    expect(curvatureSlope(cubic, 1)!.perLength).toBeCloseTo(-0.264, 6);
    expect(curvatureSlope(cubic, 1)!.perParameter).toBeCloseTo(-0.264 * Math.sqrt(10), 6);
    expect(SLOPE_STEP).toBe(1e-5);
    // And the quotient rule on src/math's derivatives agrees.
    expect(analyticSlope(cubic, 1)).toBeCloseTo(-0.264, 12);
  });

  it('is null where the speed is 0 (κ undefined)', () => {
    const stopped = [
      [0, 0],
      [0, 0],
      [1, 1],
      [2, 0],
    ];
    expect(curvatureSlope(stopped, 0)).toBeNull();
  });
});

// The scene's points (0, 0), (1, 1), (2, 0), (3, 0), worked by hand.
//
// Natural spline (uniform p̄): x = p̄ (x′ = 1, x″ = x‴ = 0). y″ at the points is
// M0 = M3 = 0 and 4M1 + M2 = 6(0 − 2 + 0), M1 + 4M2 = 6(1 − 0 + 0): M1 = −3.6,
// M2 = 2.4. Piece 0: y = 1.6p − 0.6p³, y‴ = −3.6; piece 1: y‴ = 6; piece 2: y‴ = −2.4.
// At p̄ = 1: y′ = −0.2, y″ = −3.6, |P′|² = 1.04:
//   κ = y″/1.04^{3/2} = −3.6/1.060596 = −3.394318 from both sides (C², so G²);
//   dκ/dp̄ = y‴/1.04^{3/2} − 3y″(y′y″)/1.04^{5/2} = y‴/1.060596 + 7.776/1.103020,
//   before: −3.394318 + 7.049753 = 3.655435, dκ/ds = 3.655435/1.019804 = 3.584433;
//   after: 5.657197 + 7.049753 = 12.706950, dκ/ds = 12.706950/1.019804 = 12.460173;
//   the jump is Δy‑‴/|P′|⁴ = 9.6/1.0816 = 8.875740: not G³.
// At p̄ = 2: y′ = −0.8, y″ = 2.4, |P′|² = 1.64: κ = 2.4/2.100229 = 1.142735;
//   dκ/dp̄ = y‴/2.100229 + 13.824/3.444376 = y‴/2.100229 + 4.013500, over |P′| = 1.280625:
//   before (y‴ = 6) 5.364838, after (y‴ = −2.4) 2.241697, jump −8.4/1.64² = −3.123141.
//
// Catmull-Rom (end gradients 0, D1 = (P2 − P0)/2 = (1, 0), D2 = (P3 − P1)/2 = (1, −0.5)):
//   at p̄ = 1, P′ = (1, 0); before P″ = 6(P0 − P1) + 4D1 = (−2, −6), κ = −6;
//   after P″ = 6(P2 − P1) − 4D1 − 2D2 = (0, −5), κ = −5: κ jumps, not G².
//   At p̄ = 2, P′ = (1, −0.5), |P′|³ = 1.25^{3/2} = 1.397542; before P″ = (0, 4),
//   κ = 4/1.397542 = 2.862167; after P″ = (2, 2), κ = (2 + 1)/1.397542 = 2.146625.

describe('G², G³ and C^(n−1) at the joins of the scene’s splines', () => {
  const m = derive(opened());
  const { natural, catmullJoins, catmull } = m.joins!;

  it('the natural spline: κ equal on both sides (G²), dκ/ds not (not G³)', () => {
    expect(natural.map((j) => j.s)).toEqual([1, 2]);
    const [one, two] = natural;
    expect(one.first.before).toEqual([expect.closeTo(1, 12), expect.closeTo(-0.2, 12)]);
    expect(one.second.after).toEqual([expect.closeTo(0, 12), expect.closeTo(-3.6, 12)]);
    expect(one.kappa!.before).toBeCloseTo(-3.394318, 6);
    expect(one.kappa!.after).toBeCloseTo(one.kappa!.before, 12);
    expect(one.slope!.before.perLength).toBeCloseTo(3.584433, 6);
    expect(one.slope!.after.perLength).toBeCloseTo(12.460173, 6);
    expect(one.slope!.after.perLength - one.slope!.before.perLength).toBeCloseTo(
      9.6 / 1.04 ** 2,
      6,
    );
    expect(two.kappa!.before).toBeCloseTo(1.142735, 6);
    expect(two.kappa!.after).toBeCloseTo(two.kappa!.before, 12);
    expect(two.slope!.before.perLength).toBeCloseTo(5.364838, 6);
    expect(two.slope!.after.perLength).toBeCloseTo(2.241697, 6);
    expect(two.slope!.after.perLength - two.slope!.before.perLength).toBeCloseTo(
      -8.4 / 1.64 ** 2,
      6,
    );
    expect(natural.map(naturalJoinName)).toEqual(['G², not G³', 'G², not G³']);
  });

  it('agrees with src/math: the spline, κ at each side, and dκ/ds by the quotient rule', () => {
    const segments = cubicSplineC2(opened().points);
    expect(m.plane!.pieces.segments).toEqual(segments);
    natural.forEach((j, k) => {
      const [left, right] = [segments[k], segments[k + 1]];
      expect(j.kappa!.before).toBe(bezierCurvature(left, 1));
      expect(j.kappa!.after).toBe(bezierCurvature(right, 0));
      expect(j.slope!.before.perLength).toBeCloseTo(analyticSlope(left, 1), 6);
      expect(j.slope!.after.perLength).toBeCloseTo(analyticSlope(right, 0), 6);
    });
  });

  it('the Catmull-Rom spline of the same points: C¹, κ jumps (not G²)', () => {
    expect(catmull.pieces.segments).toEqual(catmullRomSegments(opened().points, 0));
    expect(catmull.pieces.joins.map((j) => j.continuity)).toEqual(['C1', 'C1']);
    expect(catmullJoins[0].kappa!.before).toBeCloseTo(-6, 12);
    expect(catmullJoins[0].kappa!.after).toBeCloseTo(-5, 12);
    expect(catmullJoins[1].kappa!.before).toBeCloseTo(2.862167, 6);
    expect(catmullJoins[1].kappa!.after).toBeCloseTo(2.146625, 6);
    expect(catmullJoins.map((j) => catmullJoinName(j, 'C1'))).toEqual([
      'Catmull-Rom C¹, not G²',
      'Catmull-Rom C¹, not G²',
    ]);
  });

  it('walks the spline, C², G², the kinks, the Catmull-Rom spline and what G³ needs, with these numbers', () => {
    const steps = Array.from({ length: lesson.steps!.count(opened()) + 1 }, (_, k) => {
      const s = opened(k);
      return [
        derive(s).shown.name,
        lesson.steps!.describe(s, k),
        lesson.steps!.formula!(derive(s), s),
      ];
    });
    expect(steps.map(([name]) => name)).toEqual([
      'spline',
      'c2',
      'kappa',
      'slopes',
      'catmull',
      'g3',
    ]);
    expect(steps[1][1]).toBe('At each join P′ and P″ are the same on both sides: the spline is C²');
    expect(steps[2][1]).toBe(
      'κ against p̄ has one value on both sides of each join (−3.394 at p̄ = 1): the spline is G²',
    );
    expect(steps[3][1]).toBe(
      'But the slope dκ/ds jumps at each join (3.584 → 12.46 at p̄ = 1): a kink in κ, so not G³',
    );
    expect(steps[3][2]).toMatch(/= 3\.584 \\ne .* = 12\.460,\\ \\text\{difference \} 8\.876/);
    expect(steps[3][2]).toMatch(/difference \} -3\.123/);
    expect(steps[3][2]).toMatch(/h = 10\^\{-5\}\)$/);
    expect(steps[4][1]).toBe(
      'Dashed: the Catmull-Rom spline of the same points, only C¹: κ jumps at each join (−6 → −5 at p̄ = 1), so not G²',
    );
    expect(steps[5][1]).toBe(
      'G³ needs dκ/ds continuous too: degree n gives Cⁿ⁻¹, so cubic pieces give C², and C³ takes degree 4 or more',
    );
  });

  it('draws something new at every step, on the curve and the plot only', () => {
    let before = drawState(lesson, opened(0)).svg;
    for (let k = 1; k <= lesson.steps!.count(opened()); k++) {
      const now = drawState(lesson, opened(k)).svg;
      expect(now, `step ${k}`).not.toBe(before);
      before = now;
    }
    // The slopes' tangents come with their step, the joins' names with the last.
    expect(drawState(lesson, opened(3)).texts).not.toContain('G², not G³');
    expect(drawState(lesson, opened(5)).texts).toContain('G², not G³');
    expect(lesson.figuresShown!(opened())).toEqual(['curve', 'plot']);
  });

  it('writes the Catmull-Rom spline’s κ at the cursor beside the natural spline’s, once it is drawn', () => {
    const state = opened(4);
    // The cursor at t is p̄ = pieces · t: piece i = ⌊p̄⌋ at u = p̄ − i, κ from src/math.
    const pieces = catmullRomSegments(state.points, 0);
    const at = state.t * pieces.length;
    const i = Math.min(Math.floor(at), pieces.length - 1);
    const kappa = bezierCurvature(pieces[i], at - i);
    const texts = drawState(lesson, state).texts;
    const shown = texts.find((x) => x.startsWith('κ of Catmull-Rom = '));
    expect(shown, texts.join(' | ')).toBeDefined();
    expect(Number(shown!.slice('κ of Catmull-Rom = '.length).replace('−', '-'))).toBeCloseTo(
      kappa,
      2,
    );
    // Before its step, neither the curve nor its value.
    expect(drawState(lesson, opened(3)).texts.some((x) => x.startsWith('κ of Catmull-Rom ='))).toBe(
      false,
    );
  });

  it('works on the natural spline whatever the link says', () => {
    const { state, issues } = normalizeState(lesson, { ...opened(), source: 'bezier' });
    expect((state as CurvatureState).source).toBe('natural');
    expect(issues).toHaveLength(1);
  });
});
