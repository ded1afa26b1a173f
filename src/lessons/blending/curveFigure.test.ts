import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import { type BlendingState, schema } from './state';

// The curve is not drawn again while what it is drawn from stays the same (a
// drag of μ before the step that draws anything at μ): so the same must give
// the same picture, at every step of every scene.
describe('the curve figure, drawn from its state', () => {
  const figure = lesson.figures.find((f) => f.id === 'curve')!;
  const theme = makeTheme(false, false);
  const drawn = (state: BlendingState) => {
    const model = lesson.derive(state);
    const { svg } = drawHeadless(figure, model, { width: 640, height: 480, theme });
    return { from: figure.drawnFrom!(model), svg: svg.toSvg(640, 480) };
  };
  const same = (a: readonly unknown[], b: readonly unknown[]) =>
    a.length === b.length && a.every((x, i) => Object.is(x, b[i]));

  it('draws the same picture whenever it is drawn from the same values, and skips μ until a step uses it', () => {
    let skipped = 0;
    let used = 0;
    for (const scene of lesson.scenes!) {
      const start = scene.apply(defaultsOf(schema) as BlendingState) as BlendingState;
      for (let step = 0; step <= lesson.steps!.count(start); step++) {
        const state: BlendingState = { ...start, step, mu: 0.3 };
        const a = drawn(state);
        const b = drawn({ ...state, mu: 0.65 });
        if (same(a.from, b.from)) {
          skipped++;
          expect(b.svg, `${scene.id} step ${step}`).toBe(a.svg);
        } else {
          used++;
          // Drawn again, it is because the picture moved with μ.
          expect(b.svg, `${scene.id} step ${step}`).not.toBe(a.svg);
        }
      }
    }
    // The cubic's first steps (the points, their polygon) draw nothing at μ.
    expect(skipped).toBeGreaterThanOrEqual(2);
    expect(used).toBeGreaterThan(skipped);
  });

  it('is drawn again when the points, the comparison or the step change', () => {
    const state = { ...(defaultsOf(schema) as BlendingState), step: 0 };
    const from = figure.drawnFrom!(lesson.derive(state));
    const p = state.p.map((q) => [...q] as [number, number]);
    p[1][1] += 0.5;
    for (const change of [
      { p },
      { step: 1 },
      { comparison: 'hermite' },
    ] as Partial<BlendingState>[]) {
      const other = figure.drawnFrom!(lesson.derive({ ...state, ...change }));
      expect(same(other, from), JSON.stringify(Object.keys(change))).toBe(false);
    }
  });
});
