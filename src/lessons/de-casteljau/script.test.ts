import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { drawHeadless } from '../../app/headless';
import type { LabelBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import { constructionFigure } from './figure';
import lesson from './lesson';
import type { DeCasteljauModel } from './model';
import { checkScript, drawState } from '../../kit/scriptChecks';
import { type DeCasteljauState, schema } from './state';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: DeCasteljauState) => lesson.derive(s) as DeCasteljauModel;
const describeStep = (s: DeCasteljauState, k: number) => lesson.steps!.describe(s, k);
const stepFormula = (m: DeCasteljauModel, s: DeCasteljauState) => lesson.steps!.formula!(m, s);
/** What a step shows, in the words of the lecture's construction. */
const revealed = (m: DeCasteljauModel) => ({
  polygon: m.shown.has('polygon'),
  levels: m.shown.count('level'),
  curve: m.shown.has('curve'),
});

const state = (changes: Partial<DeCasteljauState>): DeCasteljauState => ({
  ...defaultsOf(schema),
  ...changes,
});

describe('the script of the de Casteljau construction', () => {
  it('every scene steps from little to all, in at most 20 steps, with plain captions', () =>
    checkScript(lesson));

  it('opens on the arch cubic at step 0, so the first press is the first step', () => {
    const defaults = defaultsOf(schema);
    // Step 0 the points, 1 the polygon, 2–4 the levels, 5 the curve.
    expect(lesson.steps!.count(defaults)).toBe(5);
    expect(defaults.step).toBe(0);
    expect({ ...lesson.scenes![0].apply(defaults), step: 0 }).toEqual(defaults);
  });

  it('builds the first scene at Figure 5’s parameter: the lecture notes draw it at μ ≈ 0.6', () => {
    const cubic = lesson.scenes![0];
    expect(cubic.id).toBe('cubic');
    expect(cubic.apply(defaultsOf(schema)).t).toBe(0.6);
    expect(cubic.label).toBe('Cubic at t = 0.6, as Figure 5');
    // No scene calls the lesson's own data the lecture's.
    for (const scene of lesson.scenes!) expect(scene.label).not.toMatch(/lecture/i);
  });

  it('step 0 shows only the control points: no polygon, no level, no curve', () => {
    const m = derive(state({ step: 0 }));
    expect(revealed(m)).toEqual({ polygon: false, levels: 0, curve: false });
    expect(drawState(lesson, m.state).elements).toBe(0);
    expect(describeStep(m.state, 0)).toBe('The 4 control points P₀ … P₃, and nothing else yet');
  });

  it('each step adds one thing', () => {
    const shown = [0, 1, 2, 3, 4, 5].map((step) => revealed(derive(state({ step }))));
    expect(shown).toEqual([
      { polygon: false, levels: 0, curve: false },
      { polygon: true, levels: 0, curve: false },
      { polygon: true, levels: 1, curve: false },
      { polygon: true, levels: 2, curve: false },
      { polygon: true, levels: 3, curve: false },
      { polygon: true, levels: 3, curve: true },
    ]);
  });

  it('gives each step its formula with the numbers worked by hand', () => {
    const at = (step: number) => {
      const s = state({ step });
      return stepFormula(derive(s), s);
    };
    // Level 1 at t = 0.6: P1,0 = 0.4·(0, 0) + 0.6·(1, 2) = (0.6, 1.2).
    expect(at(2)).toBe(
      'P_{1,0} = 0.4\\cdot(0.000,\\ 0.000) + 0.6\\cdot(1.000,\\ 2.000) = (0.600,\\ 1.200)',
    );
    // P(0.6) = 0.064·P0 + 0.288·P1 + 0.432·P2 + 0.216·P3
    //        = (0.288 + 1.296 + 0.864, 0.576 + 0.864) = (2.448, 1.44).
    expect(at(4)).toMatch(/^P\(0\.6\) = P_\{3,0\} = .* = \(2\.448,\\ 1\.440\)$/);
    expect(at(5)).toBe('P(0.6) = \\sum_{i=0}^{3} W(3,i,0.6)\\,P_i = (2.448,\\ 1.440)');
    expect(describeStep(state({}), 3)).toBe(
      'Level 2: every edge of level 1 cut at t = 0.6, 2 new points',
    );
  });

  it('traces P(t) only once the construction reaches it', () => {
    expect(constructionFigure.trail!(derive(state({ step: 3 })))).toBeNull();
    const p = constructionFigure.trail!(derive(state({ step: 4 })))!;
    expect(p[0]).toBeCloseTo(2.448, 12);
    expect(p[1]).toBeCloseTo(1.44, 12);
  });

  it('says what degenerate control points do', () => {
    const note = (p: [number, number][]) => derive(state({ p })).note;
    expect(
      note([
        [1, 1],
        [1, 1],
        [1, 1],
      ]),
    ).toMatch(/one spot.*single point/);
    expect(
      note([
        [0, 0],
        [2, 1],
        [1, 0.5],
        [4, 2],
      ]),
    ).toMatch(/one line/);
    expect(
      note([
        [0, 0],
        [1, 2],
        [1, 2],
        [4, 0],
      ]),
    ).toMatch(/^P1 and P2 are on one spot/);
    expect(
      note([
        [0, 0],
        [1, 2],
        [3, 2],
        [4, 0],
      ]),
    ).toBeNull();
    // Points on one spot are named once, not with labels on top of each other.
    const stacked = lesson.figures[0].handles!(
      derive(
        state({
          p: [
            [0, 0],
            [2, 2],
            [2, 2],
            [4, 0],
          ],
        }),
      ),
    );
    expect(stacked.map((h) => [h.label, h.showLabel])).toEqual([
      ['P_{0}', true],
      ['P_{1} = P_{2}', true],
      ['P_{2}', false],
      ['P_{3}', true],
    ]);
    // The figure says it too.
    expect(
      drawState(
        lesson,
        state({
          p: [
            [1, 1],
            [1, 1],
          ],
        }),
      ).texts.join(' '),
    ).toMatch(/one spot/);
  });

  it('labels the crowded levels of the loop apart, and clear of the handles’ labels', () => {
    for (const preset of lesson.scenes!) {
      const m = derive(preset.apply(defaultsOf(schema)));
      // As the page draws it: the construction, the handles and their names.
      const figure = lesson.figures.find((f) => f.id === constructionFigure.id)!;
      const { painter } = drawHeadless(figure, m, {
        width: 900,
        height: 560,
        theme: makeTheme(false, false),
      });
      const boxes = painter.labels;
      expect(boxes.filter((b) => /^P_\{\d\}$/.test(b.text)).length, preset.id).toBeGreaterThan(0);
      const overlap = (a: LabelBox, b: LabelBox) =>
        Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x) > 1 &&
        Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y) > 1;
      for (let i = 0; i < boxes.length; i++)
        for (let j = i + 1; j < boxes.length; j++)
          expect(
            overlap(boxes[i], boxes[j]),
            `${preset.id}: ${boxes[i].text} / ${boxes[j].text}`,
          ).toBe(false);
    }
  });
});
