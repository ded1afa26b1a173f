import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { checkScript, drawState } from '../../kit/scriptChecks';
import { quadraticFigure } from './figure';
import lesson from './lesson';
import { derive } from './model';
import { describeStep, stepFormula } from './script';
import { type QuadraticState, schema } from './state';

const state = (changes: Partial<QuadraticState>): QuadraticState => ({
  ...defaultsOf(schema),
  ...changes,
});
const formulaAt = (changes: Partial<QuadraticState>) => {
  const s = state(changes);
  return stepFormula(derive(s), s);
};

describe('the script of the quadratic lesson', () => {
  it('every scene steps from little to all, in at most 20 steps, with plain captions', () =>
    checkScript(lesson));

  it('opens on Figure 1 at its last step, and its step 0 draws nothing but the points', () => {
    const defaults = defaultsOf(schema);
    expect(lesson.scenes![0].apply(defaults)).toEqual(defaults);
    expect(defaults.step).toBe(5);
    expect(drawState(lesson, state({ step: 0 })).elements).toBe(0);
  });

  it('writes the parabola of Figure 1 with its numbers: y = −0.375x² + 1.75x + 1', () => {
    // Through (0, 1), (2, 3), (4, 2): a0 = 1, 4a2 + 2a1 = 2, 16a2 + 4a1 = 1, so a2 = −3/8, a1 = 7/4.
    expect(formulaAt({ step: 1 })).toBe('y = -0.3750\\,x^2 + 1.7500\\,x + 1.0000');
    // Through (0, 0), (1, 2), (4, 1): y = −7/12 x² + 31/12 x, no constant term.
    expect(
      formulaAt({
        step: 1,
        p: [
          [0, 0],
          [1, 2],
          [4, 1],
        ],
      }),
    ).toBe('y = -0.5833\\,x^2 + 2.5833\\,x');
    // At μ1 = ½: a0 = P0, a2 = (P1 − P0 − ½(P2 − P0))/(−¼) = (0, −6), a1 = P2 − P0 − a2 = (4, 7).
    expect(formulaAt({ step: 2 })).toBe(
      'P(\\mu) = (0.000,\\ -6.000)\\,\\mu^2 + (4.000,\\ 7.000)\\,\\mu + (0.000,\\ 1.000)',
    );
  });

  it('says in words why the first idea fails', () => {
    const sameX = state({
      p: [
        [1, 0],
        [1, 2.5],
        [3.5, 1.5],
      ],
    });
    expect(describeStep(sameX, 1)).toBe(
      'First idea, a parabola y(x): there is none, P0 and P1 share x = 1',
    );
    expect(stepFormula(derive({ ...sameX, step: 1 }), { ...sameX, step: 1 })).toBeNull();
  });

  it('names three points on one spot once, not three labels on top of each other', () => {
    const handles = quadraticFigure.handles!(
      derive(
        state({
          p: [
            [1, 1],
            [1, 1],
            [1, 1],
          ],
        }),
      ),
    );
    expect(handles.map((h) => [h.label, h.showLabel])).toEqual([
      ['P_0 = P_1 = P_2', true],
      ['P_1', false],
      ['P_2', false],
    ]);
  });
});
