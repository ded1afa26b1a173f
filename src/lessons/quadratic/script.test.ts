import { describe, expect, it } from 'vitest';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import { drawHeadless } from '../../app/headless';
import { checkScript, drawState } from '../../kit/scriptChecks';
import { seriesColour } from '../../kit/seriesColours';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import { construction } from './script';
import { LAST_STEP, type QuadraticState, schema } from './state';

const state = (changes: Partial<QuadraticState>): QuadraticState => ({
  ...defaultsOf(schema),
  ...changes,
});
const captionAt = (changes: Partial<QuadraticState>, k: number) =>
  lesson.steps!.describe(state(changes), k);
const formulaAt = (changes: Partial<QuadraticState>) => {
  const s = state(changes);
  return lesson.steps!.formula!(lesson.derive(s), s);
};

describe('the script of the quadratic lesson', () => {
  it('every scene steps from little to all, in at most 20 steps, with plain captions', () =>
    checkScript(lesson));

  it('names its six steps in the lecture’s order, the last one the schema’s', () => {
    expect(construction.steps.map((s) => s.name)).toEqual([
      'points',
      'parabola',
      'parametric',
      'ticks',
      'family',
      'rules',
    ]);
    expect(construction.lastStep(defaultsOf(schema))).toBe(LAST_STEP);
  });

  it('opens on Figure 1 at step 0, which draws nothing but the points', () => {
    const defaults = defaultsOf(schema);
    expect({ ...lesson.scenes![0].apply(defaults), step: 0 }).toEqual(defaults);
    expect(defaults.step).toBe(0);
    expect(drawState(lesson, state({ step: 0 })).elements).toBe(0);
  });

  it('keeps the link: the points under p, in the same order, old links open the same points', () => {
    expect(encodeState(schema, defaultsOf(schema))).toBe('p=0,1;2,3;4,2&mu=0.5&step=0');
    const decoded = decodeState(schema, 'p=2,0;2,1;2,3&step=1');
    expect(decoded.issues).toEqual([]);
    expect(decoded.state).toEqual({
      points: [
        [2, 0],
        [2, 1],
        [2, 3],
      ],
      mu: 0.5,
      step: 1,
    });
  });

  it('gives the three points with their numbers at step 0', () => {
    expect(captionAt({}, 0)).toBe('Three points P₀, P₁, P₂: we want a smooth curve through them');
    expect(formulaAt({ step: 0 })).toBe(
      'P_0 = (0.000,\\ 1.000),\\quad P_1 = (2.000,\\ 3.000),\\quad P_2 = (4.000,\\ 2.000)',
    );
  });

  it('writes the parabola of Figure 1 with its numbers: y = −0.375x² + 1.75x + 1', () => {
    expect(captionAt({}, 1)).toBe(
      'First idea: the parabola y(x) = a₂x² + a₁x + a₀ through the three points',
    );
    // Through (0, 1), (2, 3), (4, 2): a0 = 1, 4a2 + 2a1 = 2, 16a2 + 4a1 = 1, so a2 = −3/8, a1 = 7/4.
    expect(formulaAt({ step: 1 })).toBe('y = -0.3750\\,x^2 + 1.7500\\,x + 1.0000');
    // Through (0, 0), (1, 2), (4, 1): y = −7/12 x² + 31/12 x, no constant term.
    expect(
      formulaAt({
        step: 1,
        points: [
          [0, 0],
          [1, 2],
          [4, 1],
        ],
      }),
    ).toBe('y = -0.5833\\,x^2 + 2.5833\\,x');
  });

  it('writes the parametric quadratic at μ1 = ½ and its dots at μ = 0.1, 0.5, 0.9', () => {
    expect(captionAt({}, 2)).toBe(
      'Instead, a parametric quadratic P(μ): P₀ at μ = 0, P₁ at μ = μ₁ = 0.5, P₂ at μ = 1',
    );
    // At μ1 = ½: a0 = P0, a2 = (P1 − P0 − ½(P2 − P0))/(−¼) = (0, −6), a1 = P2 − P0 − a2 = (4, 7).
    expect(formulaAt({ step: 2 })).toBe(
      'P(\\mu) = (0.000,\\ -6.000)\\,\\mu^2 + (4.000,\\ 7.000)\\,\\mu + (0.000,\\ 1.000)',
    );
    // P(μ) = (4μ, −6μ² + 7μ + 1): P(0.1) = (0.4, 1.64), P(0.5) = (2, 3) = P1, P(0.9) = (3.6, 2.44).
    expect(captionAt({}, 3)).toBe(
      'Dots at equal steps of μ (0, 0.1, …, 1): where they spread out, P(μ) moves fast',
    );
    expect(formulaAt({ step: 3 })).toBe(
      'P(0.1) = (0.400,\\ 1.640),\\quad P(0.5) = (2.000,\\ 3.000),\\quad P(0.9) = (3.600,\\ 2.440)',
    );
  });

  it('lists the family and the slider’s μ1, then the rules with d0 = 2√2, d1 = √5', () => {
    expect(captionAt({}, 4)).toBe(
      'One set of points, four curves, as in Figure 2: μ₁ = 0.2, 0.35, 0.5, 0.8',
    );
    expect(formulaAt({ step: 4, mu: 0.3 })).toBe(
      "\\mu_1 = 0.2,\\ 0.35,\\ 0.5,\\ 0.8\\quad\\text{(and the slider's } \\mu_1 = 0.3\\text{)}",
    );
    expect(captionAt({}, 5)).toBe(
      'Choosing μ₁ from the points: uniform, chord length, centripetal',
    );
    // d0 = |(2, 2)| = 2.828, d1 = |(2, −1)| = 2.236; chord 2.828 / 5.064 = 0.558;
    // centripetal 1.682 / (1.682 + 1.495) = 0.529.
    expect(formulaAt({ step: 5 })).toBe(
      // Each rule a group, broken only between them (termRow).
      '{\\text{uniform } \\tfrac12},\\allowbreak\\quad {\\text{chord } \\frac{d_0}{d_0 + d_1} = \\frac{2.828}{5.064} = 0.558},\\allowbreak\\quad {\\text{centripetal } \\frac{\\sqrt{d_0}}{\\sqrt{d_0} + \\sqrt{d_1}} = 0.529}',
    );
  });

  it('says in words why the first idea fails', () => {
    const sameX = state({
      step: 1,
      points: [
        [1, 0],
        [1, 2.5],
        [3.5, 1.5],
      ],
    });
    expect(lesson.steps!.describe(sameX, 1)).toBe(
      'First idea, a parabola y(x): there is none, P₀ and P₁ share x = 1',
    );
    expect(lesson.steps!.formula!(lesson.derive(sameX), sameX)).toBeNull();
    const backwards = state({
      points: [
        [0, 0],
        [4, 2],
        [2, 3.5],
      ],
    });
    expect(lesson.steps!.describe(backwards, 1)).toBe(
      'First idea, a parabola y(x): it exists, but visits the points out of order',
    );
  });

  it('reveals by name: y(x) until the family, P(μ) from its step, its dots from the next', () => {
    const at = (step: number) => lesson.derive(state({ step })).shown;
    expect(at(0).has('parabola')).toBe(false);
    expect(at(1).is('parabola')).toBe(true);
    expect(at(3).has('parametric') && at(3).has('ticks') && !at(3).has('family')).toBe(true);
    expect(at(5).last && at(5).is('rules')).toBe(true);
  });

  it('keeps the curves while the points and μ1 are the same: a step solves nothing again', () => {
    const base = state({});
    const first = lesson.derive({ ...base, step: 2 });
    const last = lesson.derive({ ...base, step: 5 });
    expect(last.parametric.all).toBe(first.parametric.all);
    expect(last.explicit).toBe(first.explicit);
    expect(last.bounds).toBe(first.bounds);
    // A new μ1 solves P(μ) again, but not y(x), which reads only the points.
    const moved = lesson.derive({ ...base, mu: 0.3 });
    expect(moved.parametric.all).not.toBe(first.parametric.all);
    expect(moved.explicit).toBe(first.explicit);
  });

  it('names three points on one spot once, not three labels on top of each other', () => {
    const handles = lesson.figures[0].handles!(
      lesson.derive(
        state({
          points: [
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

  it('moves a point by its handle, and never adds or removes one', () => {
    const figure = lesson.figures[0];
    const s = state({});
    const moved = figure.moveHandle!(s, 'p1', [2.5, 3.5], lesson.derive(s));
    expect(moved.points).toEqual([
      [0, 1],
      [2.5, 3.5],
      [4, 2],
    ]);
    expect(figure.addPoint).toBeUndefined();
    // Three points, no more and no fewer: no delete, no add (as before the kit).
    expect(figure.removeHandle).toBeUndefined();
  });
});

describe('the members of the family, named on screen', () => {
  /** The curve figure of the last step drawn headless at `width` × `height`: its members' tags, and every text drawn. */
  const drawnAt = (width: number, height: number) => {
    const s = state({ step: LAST_STEP });
    const { painter, svg } = drawHeadless(lesson.figures[0], lesson.derive(s), {
      width,
      height,
      theme: makeTheme(false, false),
    });
    painter.placeLabels();
    const member = (text: string) => /^(Uniform|Chord length|Centripetal|chosen): /.test(text);
    return { tags: painter.labels.filter((l) => member(l.text)), named: svg.texts.filter(member) };
  };

  it('draw a rule that is the chosen μ₁ over the chosen curve, dashed, so its colour is seen', () => {
    // The default μ₁ is 0.5, uniform's: drawn beneath the chosen curve, the
    // blue the key names was nowhere on the figure.
    const s = state({ step: LAST_STEP });
    expect(s.mu).toBe(0.5);
    const theme = makeTheme(false, false);
    const m = lesson.derive(s);
    const uniform = m.parametric.members.find((member) => member.text.startsWith('Uniform'))!;
    const blue = seriesColour(theme.palette, uniform.colour!);
    const { svg } = drawHeadless(lesson.figures[0], m, { width: 900, height: 560, theme });
    const strokes = svg.elements.filter((e) => e.startsWith('<path') && e.includes('fill="none"'));
    // The chosen curve: the ink stroke of 100 pieces (μ = 0, 1/100, …, 1), not a key's sample.
    const pieces = (e: string) => (e.match(/L/g) ?? []).length;
    const chosen = strokes.findIndex(
      (e) => e.includes(`stroke="${theme.curve}"`) && pieces(e) === 100,
    );
    const over = strokes.reduce(
      (last, e, i) => (e.includes(`stroke="${blue}"`) && e.includes('stroke-dasharray') ? i : last),
      -1,
    );
    expect(chosen).toBeGreaterThanOrEqual(0);
    expect(over).toBeGreaterThan(chosen);
  });

  it('beside their curves where the figure has room, in a key where it has not (a phone)', () => {
    // A laptop's figure: four tags, at their curves' own spots, not in a column.
    const wide = drawnAt(900, 560).tags;
    expect(wide).toHaveLength(4);
    expect(new Set(wide.map((l) => Math.round(l.x))).size).toBeGreaterThan(1);
    // A phone's 340 px: the tags together are wider than the figure; on it they
    // covered the very curves they named. No tags: the four names in a key.
    const phone = drawnAt(340, 420);
    expect(phone.tags).toEqual([]);
    expect(phone.named).toHaveLength(4);
  });
});
