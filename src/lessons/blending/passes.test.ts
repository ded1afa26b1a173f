import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { bezierPoint, lagrangePoint, nearestOnBezierPieces } from '../../math';
import { equallySpacedNodes } from './families';
import lesson from './lesson';
import type { BlendingModel } from './model';
import { WORDS_SLIP } from './notesKey';
import { lagrangeAsBezier, passes } from './passes';
import { passesScript } from './passesScript';
import { type BlendingState, schema } from './state';

// The lecture cubic P0 = (0, 0), P1 = (1, 2), P2 = (3, 2), P3 = (4, 0), worked by hand.
//
// Its Lagrange curve on the nodes 0, 1/3, 2/3, 1: y(μ) is symmetric about μ = ½
// and 0 at both ends, so y = cμ(1 − μ), and y(1/3) = 2c/9 = 2 gives c = 9:
// y = 9μ − 9μ². x(μ) − 2 is odd about μ = ½: x = 2 + a(μ − ½) + b(μ − ½)³ with
// x(1) = 4 and x(2/3) = 3, so a/2 + b/8 = 2, a/6 + b/216 = 1: b = −9, a = 6.25,
// and multiplied out x = −0.5μ + 13.5μ² − 9μ³. In the Bernstein basis (c₀, c₀ +
// c₁/3, c₀ + 2c₁/3 + c₂/3, Σc for a cubic c₀ + c₁μ + c₂μ² + c₃μ³):
// x: 0, −1/6, −1/3 + 4.5 = 25/6, 4;  y: 0, 3, 6 − 3 = 3, 0.
// So L is the Bézier curve (0, 0), (−1/6, 3), (25/6, 3), (4, 0).
//
// The Bézier curve itself: x(μ) = 3μ + 3μ² − 2μ³, y(μ) = 6μ(1 − μ) ≤ 1.5, so
// P1 = (1, 2) is at least 0.5 from it. Nearest by hand: μ = 0.33 gives (1.2448,
// 1.3266), d² = 0.0599 + 0.4535 = 0.5134; μ = 0.34 gives (1.2882, 1.3464),
// d² = 0.0831 + 0.4272 = 0.5102; μ = 0.345 gives d² = 0.5110: the nearest
// point is near μ = 0.34, d = √0.5102 ≈ 0.714. P2 is P1's mirror image in
// x = 2, and so is the curve: the same 0.714. P0 and P3 are the curve's ends: 0.

const cubic: BlendingState = defaultsOf(schema);
const derive = (s: BlendingState) => lesson.derive(s) as BlendingModel;
const opened = () => {
  const scene = lesson.scenes!.find((s) => s.id === 'interpolating')!;
  return { ...(scene.apply(cubic) as BlendingState), step: 0 };
};
const walk = (s: BlendingState) =>
  Array.from({ length: lesson.steps!.count(s) + 1 }, (_, step) => {
    const at = { ...s, step };
    return [lesson.steps!.describe(at, step), lesson.steps!.formula!(derive(at), at)];
  });
const close = (actual: readonly number[], expected: readonly number[], digits = 12) =>
  expected.forEach((v, i) => expect(actual[i]).toBeCloseTo(v, digits));

describe('interpolating or approximating: the distance of each point to each curve', () => {
  it('writes the Lagrange curve of the lecture cubic as the Bézier curve (0, 0), (−1/6, 3), (25/6, 3), (4, 0)', () => {
    const b = lagrangeAsBezier(cubic.p);
    [
      [0, 0],
      [-1 / 6, 3],
      [25 / 6, 3],
      [4, 0],
    ].forEach((q, i) => close(b[i], q));
    // The same curve as src/math's Lagrange polynomial, everywhere on [0, 1].
    const nodes = equallySpacedNodes(3);
    for (let k = 0; k <= 20; k++)
      close(bezierPoint(b, k / 20), lagrangePoint(nodes, cubic.p, k / 20), 12);
  });

  it('finds every point on the Lagrange curve, and only the ends on the Bézier curve', () => {
    const found = passes(cubic.p);
    found.lagrange.forEach((q) => expect(q.distance).toBeLessThan(1e-12));
    expect(found.onLagrange).toEqual([true, true, true, true]);
    expect(found.bezier.map((q) => q.distance)).toEqual([
      0,
      expect.closeTo(0.714, 3),
      expect.closeTo(0.714, 3),
      0,
    ]);
    expect(found.onBezier).toEqual([true, false, false, true]);
    // P1's nearest point, near μ = 0.34 by hand, is on the curve, and no sample is nearer.
    const nearest = found.bezier[1];
    close(nearest.point, bezierPoint(cubic.p, 0.3400747212), 8);
    let sampled = Infinity;
    for (let k = 0; k <= 20000; k++) {
      const q = bezierPoint(cubic.p, k / 20000);
      sampled = Math.min(sampled, Math.hypot(q[0] - 1, q[1] - 2));
    }
    expect(nearest.distance).toBeLessThanOrEqual(sampled);
    expect(nearest.distance).toBeCloseTo(sampled, 7);
  });

  it('holds for the lesson’s other point sets: the Lagrange curve through all, the Bézier curve through its ends', () => {
    for (const scene of lesson.scenes!) {
      const { p } = scene.apply(cubic) as BlendingState;
      const found = passes(p);
      expect(found.onLagrange.every(Boolean), scene.id).toBe(true);
      // src/math's own nearest point on the Lagrange polynomial's Bézier form agrees.
      p.forEach((q, i) =>
        expect(nearestOnBezierPieces([found.lagrangeControls], q)!.distance).toBe(
          found.lagrange[i].distance,
        ),
      );
      expect(found.onBezier[0] && found.onBezier[p.length - 1], scene.id).toBe(true);
    }
    // N = 6 and 10 zigzag: no inner point on the Bézier curve.
    const zigzag = Array.from({ length: 11 }, (_, i) => [i / 2, i % 2 === 0 ? 0 : 3]);
    expect(passes(zigzag).onBezier.slice(1, -1).some(Boolean)).toBe(false);
  });
});

describe('the scene steps through the points, each curve, and which points it passes through', () => {
  it('walks the lecture cubic with the distances in its captions and formulas', () => {
    const names = Array.from(
      { length: passesScript.lastStep(opened()) + 1 },
      (_, k) => passesScript.shown(opened(), k).name,
    );
    expect(names).toEqual([
      'points',
      'lagrangeCurve',
      'interpolating',
      'bezierCurve',
      'approximating',
    ]);
    const steps = walk(opened());
    expect(steps[0][0]).toBe(
      'The control points P₀ … P₃, for two curves: does each pass through them?',
    );
    expect(steps[2]).toEqual([
      'Interpolating: the Lagrange curve passes through every control point, each at distance 0',
      'd(P_i, L) = \\min_\\mu |L(\\mu) - P_i|:\\quad 0.000,\\ 0.000,\\ 0.000,\\ 0.000',
    ]);
    // 0.714 by hand (above).
    expect(steps[4][0]).toBe(
      'Approximating: the Bézier curve passes through P₀ and P₃ only; P₁ and P₂ stay 0.714 and 0.714 away, shaping it without lying on it',
    );
    expect(steps[4][1]).toMatch(
      /d\(P_i, P\) = \\min_\\mu \|P\(\\mu\) - P_i\|:\\quad 0\.000,\\ 0\.714,\\ 0\.714,\\ 0\.000\\end\{aligned\}$/,
    );
  });

  it('draws each curve with its weights, then its distances', () => {
    const drawn = (step: number) => derive({ ...opened(), step }).drawn;
    expect(drawn(0)).toMatchObject({
      comparedCurve: false,
      curve: false,
      compared: 0,
      bernstein: 0,
    });
    expect(drawn(1)).toMatchObject({ comparedCurve: true, compared: 4, onLagrange: false });
    expect(drawn(2)).toMatchObject({ onLagrange: true, curve: false });
    expect(drawn(3)).toMatchObject({ curve: true, bernstein: 4, onBezier: false });
    expect(drawn(4)).toMatchObject({ onLagrange: true, onBezier: true, point: false });
    // Other scenes ask nothing of the kind.
    expect(derive(cubic).passes).toBeNull();
  });

  it('says how a curve of two points passes through both', () => {
    const line = { ...opened(), p: cubic.p.slice(0, 2), step: 4 };
    expect(lesson.steps!.describe(line, 4)).toBe(
      'Here the Bézier curve passes through every control point too: distance 0 from each',
    );
  });

  it('quotes the “Splines” slides’ swapped words beside the right ones', () => {
    expect(WORDS_SLIP.written).toMatch(
      /interpolate control points \(the curve does not have to pass through them\).*approximate control points \(the curve passes through the points\)/,
    );
    expect(WORDS_SLIP.correct).toMatch(
      /^The two explanations have swapped places: an interpolating curve passes through its points/,
    );
  });
});
