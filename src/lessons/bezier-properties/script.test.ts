import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { checkScript, drawState, sceneStates } from '../../kit/scriptChecks';
import { propertiesFigure } from './figure';
import lesson from './lesson';
import type { ModelOf, PropertiesModel } from './model';
import { SCENES } from './scenes';
import { ARCH_CUBIC, type PropertiesState, schema } from './state';

const scene = (id: string, step?: number): PropertiesState => {
  const s = SCENES.find((p) => p.id === id)!.setup(defaultsOf(schema));
  return step === undefined ? s : { ...s, step };
};
/** The model, caption and formula as the shell gets them from the kit. */
const derive = (s: PropertiesState) => lesson.derive(s) as PropertiesModel;
const describeStep = (s: PropertiesState, k: number) => lesson.steps!.describe(s, k);
const stepFormula = (m: PropertiesModel, s: PropertiesState) => lesson.steps!.formula!(m, s);

describe('the script of the Bézier properties', () => {
  it('every experiment steps from little to all, in at most 20 steps, with plain captions', () =>
    checkScript(lesson));

  it('gives every one of the thirteen scenes steps, and opens on the first one at step 0', () => {
    const scenes = sceneStates(lesson);
    expect(scenes).toHaveLength(13);
    for (const { id, count } of scenes) expect(count, id).toBeGreaterThanOrEqual(4);
    const defaults = defaultsOf(schema);
    expect(defaults.step).toBe(0);
    expect({ ...lesson.scenes![0].apply(defaults), step: 0 }).toEqual(defaults);
    // Step 0 of every scene draws nothing but the handles the shell adds.
    for (const { id, at } of scenes) expect(drawState(lesson, at(0)).elements, id).toBe(0);
  });

  it('says each step in words and writes its formula with numbers worked by hand', () => {
    const ends = scene('ends', 4);
    expect(describeStep(ends, 4)).toBe(
      'It leaves along the first leg and arrives along the last, at 3 times their length',
    );
    // P′(0) = 3((1, 2) − (0, 0)) = (3, 6); P′(1) = 3((4, 0) − (3, 2)) = (3, −6).
    expect(stepFormula(derive(ends), ends)).toBe(
      "P'(0) = 3(P_1 - P_0) = (3.000,\\ 6.000),\\quad P'(1) = 3(P_{3} - P_{2}) = (3.000,\\ -6.000)",
    );
    const elevate = scene('elevate', 3);
    expect(describeStep(elevate, 3)).toBe(
      'Degree raised 2 times, to 5: the same curve, a polygon closer to it',
    );
    // Hermite data of the arch cubic: x0′ = 3(P1 − P0) = (3, 6), x1′ = 3(P3 − P2) = (3, −6).
    const hermite = scene('hermite', 2);
    expect(stepFormula(derive(hermite), hermite)).toBe(
      "x_0' = 3(P_1 - P_0) = (3.000,\\ 6.000),\\quad x_1' = 3(P_3 - P_2) = (3.000,\\ -6.000)",
    );
    expect(describeStep(scene('local', 2), 2)).toBe('P₅ moved; every other control point stayed');
  });

  it('steps through the derivative curve with the numbers worked by hand', () => {
    const at = (step: number) => {
      const s = scene('hodograph', step);
      return [describeStep(s, step), stepFormula(derive(s), s)];
    };
    // The arch's legs: (1, 2) − (0, 0) = (1, 2), (3, 2) − (1, 2) = (2, 0), (4, 0) − (3, 2) = (1, −2).
    expect(at(2)[1]).toBe(
      'P_{1} - P_{0} = (1.000,\\ 2.000),\\ P_{2} - P_{1} = (2.000,\\ 0.000),\\ P_{3} - P_{2} = (1.000,\\ -2.000)',
    );
    // Times 3: (3, 6), (6, 0), (3, −6).
    expect(at(3)).toEqual([
      'Times n = 3: the control points of the derivative, 3(Pᵢ₊₁ − Pᵢ)',
      '3(P_{1} - P_{0}) = (3.000,\\ 6.000),\\ 3(P_{2} - P_{1}) = (6.000,\\ 0.000),\\ 3(P_{3} - P_{2}) = (3.000,\\ -6.000)',
    ]);
    expect(at(4)[1]).toBe("P'(t) = \\sum_{i=0}^{2} W(2,i,t)\\,3(P_{i+1} - P_i)");
    // At t = 0.3: W(2, i, 0.3) = 0.49, 0.42, 0.09;
    // P′(0.3) = 0.49·(3, 6) + 0.42·(6, 0) + 0.09·(3, −6) = (1.47 + 2.52 + 0.27, 2.94 − 0.54) = (4.26, 2.4).
    expect(at(5)).toEqual([
      'At t = 0.3 the derivative curve gives P′(t) = (4.26, 2.4)',
      "P'(0.3) = 0.49\\cdot(3.000,\\ 6.000) + 0.42\\cdot(6.000,\\ 0.000) + 0.09\\cdot(3.000,\\ -6.000) = (4.260,\\ 2.400)",
    ]);
    // Level 2 of the construction at 0.3: P2,0 = 0.7·(0.3, 0.6) + 0.3·(1.6, 2) = (0.69, 1.02),
    // P2,1 = 0.7·(1.6, 2) + 0.3·(3.3, 1.4) = (2.11, 1.82); 3(P2,1 − P2,0) = 3(1.42, 0.8) = (4.26, 2.4).
    expect(at(6)[1]).toBe(
      "3(P_{2,1} - P_{2,0}) = 3((2.110,\\ 1.820) - (0.690,\\ 1.020)) = (4.260,\\ 2.400) = P'(0.3)",
    );
  });

  it('keeps the closed curve’s arrows short, in the view, and names P0 = P5 once', () => {
    const s = scene('closed');
    const m = derive(s) as ModelOf<'closed'>;
    // The polygon spans 6 × 4.5: size 7.5, so an arrow is at most 0.3 · 7.5 = 2.25 long.
    const length = Math.hypot(m.leaving[1][0] - m.leaving[0][0], m.leaving[1][1] - m.leaving[0][1]);
    expect(length).toBeCloseTo(2.25, 12);
    // P′(0) = 5(P1 − P0) = (−5, 15): the tip is 2.25 along it.
    expect(m.leaving[1][0]).toBeCloseTo((-5 * 2.25) / Math.hypot(5, 15), 12);
    expect(m.extent).toContainEqual(m.leaving[1]);
    // The fitted view is the control points' own box: the arrows do not set it.
    const xs = m.extent.map((q) => q[0]);
    const ys = m.extent.map((q) => q[1]);
    expect([Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)]).toEqual([
      -1, 5, 0, 4.5,
    ]);
    const texts = drawState(lesson, s).texts.join(' ');
    expect(texts).not.toMatch(/P\s*0\s*=\s*P\s*5/);
    expect(lesson.figures[0].handles!(m)[0].label).toBe('P_0 = P_{5}');
  });

  it('traces P(t) once the experiment shows it', () => {
    expect(propertiesFigure.trail!(derive(scene('ends', 4)))).toBeNull();
    // P(0.3) of the arch cubic: 0.343·P0 + 0.441·P1 + 0.189·P2 + 0.027·P3 = (1.116, 1.26).
    const p = propertiesFigure.trail!(derive(scene('ends', 5)))!;
    expect(p[0]).toBeCloseTo(1.116, 12);
    expect(p[1]).toBeCloseTo(1.26, 12);
  });

  it('stacks coincident control points under one name', () => {
    const m = derive({
      ...scene('hull'),
      points: [ARCH_CUBIC[0], ARCH_CUBIC[0], ARCH_CUBIC[3]],
    });
    expect(lesson.figures[0].handles!(m).map((h) => [h.label, h.showLabel])).toEqual([
      ['P_{0} = P_{1}', true],
      ['P_{1}', false],
      ['P_{2}', true],
    ]);
  });
});
