import { describe, expect, it } from 'vitest';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import lesson from './lesson';
import type { BlendingModel } from './model';
import { controlPoints } from './points';
import { blendingScript } from './bernsteinScript';
import { type BlendingState, schema } from './state';

// The lecture's cubic P0 = (0, 0), P1 = (1, 2), P2 = (3, 2), P3 = (4, 0) at μ = ½,
// where W(3, i, ½) = C(3, i) / 8 = 1/8, 3/8, 3/8, 1/8 and P(½) = (2, 1.5).

const cubic: BlendingState = defaultsOf(schema);
const derive = (s: BlendingState) => lesson.derive(s) as BlendingModel;
/** Caption and formula of every step, as the shell shows them. */
const walk = (s: BlendingState) =>
  Array.from({ length: blendingScript.lastStep(s) + 1 }, (_, step) => {
    const at = { ...s, step };
    return [lesson.steps!.describe(at, step), lesson.steps!.formula!(derive(at), at)];
  });

describe('the blending script, step by named step', () => {
  it('walks the cubic: the points, W(3, 0 … 3, ½), P(½), the curve', () => {
    expect(walk(cubic)).toEqual([
      [
        'The control points P₀ … P₃ and their polygon',
        'P(\\mu) = \\sum_{i=0}^{3} W(3,i,\\mu)\\,P_i',
      ],
      // W(3, 0, ½) = 1 · ½³ = 0.125
      ['The weight of P₀: W(3, 0, μ), largest at μ = 0', 'W(3,0,0.5) = 1\\cdot 0.5^{3} = 0.1250'],
      // W(3, 1, ½) = 3 · ½ · ½² = 0.375
      [
        'The weight of P₁: W(3, 1, μ), largest at μ = 1/3',
        'W(3,1,0.5) = 3\\cdot 0.5\\cdot 0.5^{2} = 0.3750',
      ],
      [
        'The weight of P₂: W(3, 2, μ), largest at μ = 2/3',
        'W(3,2,0.5) = 3\\cdot 0.5^{2}\\cdot 0.5 = 0.3750',
      ],
      ['The weight of P₃: W(3, 3, μ), largest at μ = 1', 'W(3,3,0.5) = 1\\cdot 0.5^{3} = 0.1250'],
      // (0·1 + 1·3 + 3·3 + 4·1) / 8 = 2, (0 + 2·3 + 2·3 + 0) / 8 = 1.5
      [
        'P(μ): the control points averaged with these weights',
        // Two terms a line, so the caption leaves the figure its room in presenter view (#19).
        '\\begin{aligned}P(0.5) &= 0.1250\\,(0.00,\\ 0.00) + 0.3750\\,(1.00,\\ 2.00)\\\\ &\\quad + 0.3750\\,(3.00,\\ 2.00) + 0.1250\\,(4.00,\\ 0.00)\\\\ &= (2.0000,\\ 1.5000)\\end{aligned}',
      ],
      [
        'As μ runs from 0 to 1, P(μ) traces the Bézier curve',
        'P(\\mu) = (1-\\mu)^{3}\\,P_{0} + 3\\mu(1-\\mu)^{2}\\,P_{1} + 3\\mu^{2}(1-\\mu)\\,P_{2} + \\mu^{3}\\,P_{3}',
      ],
    ]);
  });

  it('sets the weighted sum of N = 6 on two lines of terms, four and three, then the point', () => {
    // The N = 6 scene at μ = 0.3, W(6, i, 0.3) = C(6, i) 0.3ⁱ 0.7⁶⁻ⁱ by hand:
    //   0.7⁶ = 0.117649, 6·0.3·0.16807 = 0.302526, 15·0.09·0.2401 = 0.324135,
    //   20·0.027·0.343 = 0.18522, 15·0.0081·0.49 = 0.059535, 6·0.00243·0.7 = 0.010206,
    //   0.3⁶ = 0.000729 (they sum to 1).
    // x = 0.302526·0.5 + 0.324135·2 + 0.18522·3 + 0.059535·4 + 0.010206·5.5 + 0.000729·6 = 1.65384,
    // y = 0.302526·2.5 + 0.324135·3 + 0.18522·1 + 0.059535·3 + 0.010206·2.5 = 2.11806.
    const scene = lesson.scenes!.find((s) => s.id === 'degree6')!;
    const opened = scene.apply(cubic) as BlendingState;
    const six = { ...opened, step: blendingScript.stepOf(opened, 'point') };
    expect(six.step).toBe(8);
    expect(lesson.steps!.formula!(derive(six), six)).toBe(
      '\\begin{aligned}P(0.3) &= 0.1176\\,(0.00,\\ 0.00) + 0.3025\\,(0.50,\\ 2.50) + 0.3241\\,(2.00,\\ 3.00) + 0.1852\\,(3.00,\\ 1.00)' +
        '\\\\ &\\quad + 0.0595\\,(4.00,\\ 3.00) + 0.0102\\,(5.50,\\ 2.50) + 0.0007\\,(6.00,\\ 0.00)\\\\ &= (1.6538,\\ 2.1181)\\end{aligned}',
    );
  });

  it('has no comparison step: a comparison walks a script of its own', () => {
    expect(blendingScript.stepOf(cubic, 'point')).toBe(5);
    expect(blendingScript.stepOf(cubic, 'curve')).toBe(6);
    expect(blendingScript.stepOf(cubic, 'basis')).toBe(-1);
    // N = 1: P0's weight peaks at μ = 0, P₁'s at μ = 1.
    const line = { ...cubic, p: cubic.p.slice(0, 2) };
    expect(blendingScript.lastStep(line)).toBe(4);
    expect(walk(line)[2][0]).toBe('The weight of P₁: W(1, 1, μ), largest at μ = 1');
  });

  it('ends Hermite’s comparison with H₀ + H₁ = 1: those two weight points, H₂ and H₃ gradients', () => {
    const at = { ...cubic, comparison: 'hermite' as const, mu: 0.3 };
    const last = { ...at, step: lesson.steps!.count(at) };
    // H₀(0.3) = 2 · 0.027 − 3 · 0.09 + 1 = 0.784, H₁ = −0.054 + 0.27 = 0.216,
    // H₂ = 0.027 − 0.18 + 0.3 = 0.147, H₃ = 0.027 − 0.09 = −0.063; 0.784 + 0.216 = 1.
    expect(lesson.steps!.formula!(derive(last), last)).toBe(
      // Each equation a group, broken only between them (termRow).
      '{H_0(0.3) = 0.7840},\\allowbreak\\ {H_1(0.3) = 0.2160},\\allowbreak\\ {H_2(0.3) = 0.1470},\\allowbreak\\ {H_3(0.3) = -0.0630},\\allowbreak\\quad {H_0 + H_1 = 1}',
    );
  });

  it('reveals by name: the weights count up, P(μ) and the curve follow', () => {
    const shown = (step: number) => derive({ ...cubic, step }).shown;
    expect(shown(0).count('weight')).toBe(0);
    expect(shown(3).count('weight')).toBe(3);
    expect(shown(3).is('weight')).toBe(true);
    expect(shown(5).has('point')).toBe(true);
    expect(shown(5).has('curve')).toBe(false);
    expect(shown(6).last).toBe(true);
  });

  it('keeps a script shown to its end at its end after an edit', () => {
    const end = { ...cubic, step: 6 };
    // A point added at the end: N = 4, 7 presses.
    expect(controlPoints.add(end, [2, 0.5])!.step).toBe(7);
    expect(controlPoints.remove(end, 1)!.step).toBe(5);
    // In the middle of the script, the step stays.
    expect(controlPoints.add({ ...cubic, step: 2 }, [2, 0.5])!.step).toBe(2);
  });

  it('keeps the link: the comparison is still `b`, in the same place', () => {
    const state = { ...cubic, comparison: 'lagrange' as const, step: 3 };
    expect(encodeState(schema, state)).toBe('p=0,0;1,2;3,2;4,0&mu=0.5&b=lagrange&step=3');
    expect(decodeState(schema, 'b=bspline').state.comparison).toBe('bspline');
  });
});
