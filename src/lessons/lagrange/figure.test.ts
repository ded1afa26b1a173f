import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { glyphBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import { type LagrangeState, schema } from './state';

// Runge's polynomial swings far above its points near the ends; the view keeps
// to the points, so at t = 0.05 P(t) is off a wide figure (presenter view's,
// 1880 × 560 px); a phone's (342 × 230 px) is taller for its width.
describe('P(t) of the Runge polynomial', () => {
  const figure = lesson.figures.find((f) => f.id === 'curve')!;
  const runge = lesson.scenes!.find((s) => s.id === 'runge')!;
  const start = runge.apply(defaultsOf(schema) as LagrangeState) as LagrangeState;
  const state: LagrangeState = { ...start, step: lesson.steps!.count(start), t: 0.05 };
  const model = lesson.derive(state);

  for (const [where, width, height, projector] of [
    ['presenter view', 1880, 560, true],
    ['a phone', 342, 230, false],
  ] as const)
    it(`on ${where}: named on the figure, at the point or at an arrow pointing to it`, () => {
      const { painter, view } = drawHeadless(figure, model, {
        width,
        height,
        theme: makeTheme(false, projector),
      });
      const name = painter.labels.find((l) => l.text === 'P(t)');
      expect(name).toBeDefined();
      const box = glyphBox(name!);
      expect(box.x).toBeGreaterThanOrEqual(0);
      expect(box.y).toBeGreaterThanOrEqual(0);
      expect(box.x + box.width).toBeLessThanOrEqual(width);
      expect(box.y + box.height).toBeLessThanOrEqual(height);
      const [, y] = view.toScreen(model.at);
      // Off the top of the wide figure (what the arrow is for).
      if (where === 'presenter view') expect(y).toBeLessThan(0);
    });
});
