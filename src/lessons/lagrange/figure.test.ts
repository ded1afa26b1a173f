import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { glyphBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import { type LagrangeState, schema } from './state';

/** The figure `id` and the model of scene `scene`'s last step, the cursor at `t`. */
function lastStep(id: string, scene: string, t: number) {
  const figure = lesson.figures.find((f) => f.id === id)!;
  const opened = lesson.scenes!.find((s) => s.id === scene)!;
  const start = opened.apply(defaultsOf(schema) as LagrangeState) as LagrangeState;
  const state: LagrangeState = { ...start, step: lesson.steps!.count(start), t };
  return { figure, model: lesson.derive(state) };
}

// Runge's polynomial swings far above its points near the ends; the view keeps
// to the points, so at t = 0.05 P(t) is off a wide figure (presenter view's,
// 1880 × 560 px); a phone's (342 × 230 px) is taller for its width.
describe('P(t) of the Runge polynomial', () => {
  const { figure, model } = lastStep('curve', 'runge', 0.05);

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

// A 1366 × 768 projector: the basis strip is 1348 × 220 px. The five values
// at the cursor fit in one row across it (not over the plot alone), and stood
// nowhere before: the y name moved up into their row, and they were left out.
describe('the values L_k(t) at the cursor on a 1366 presenter strip', () => {
  const { figure, model } = lastStep('basis', 'five', 0.4);

  it('are all written, above the plot, clear of each other and of its y name', () => {
    const { painter, view } = drawHeadless(figure, model, {
      width: 1348,
      height: 220,
      theme: makeTheme(false, true),
    });
    const ts = model.ts;
    // L_k(t) = Π_{j≠k} (t − t_j) / (t_k − t_j), worked from the parameter values.
    const lk = (k: number) =>
      ts.reduce((p, tj, j) => (j === k ? p : (p * (0.4 - tj)) / (ts[k] - tj)), 1);
    const [, plotTop] = view.toScreen([0, model.plotBounds.maxY]);
    const values = ts.map((_, k) => {
      const label = painter.labels.find((l) => l.text.startsWith(`L_{${k}}(t) = `));
      expect(label, `L_${k}(t)`).toBeDefined();
      const written = Number(label!.text.split(' = ')[1].replace('−', '-'));
      expect(written).toBeCloseTo(lk(k), 2);
      const box = label!.frame ?? glyphBox(label!);
      expect(box.y + box.height).toBeLessThanOrEqual(plotTop);
      return box;
    });
    const name = painter.labels.find((l) => l.text === 'L_k(t)')!;
    for (const box of [...values, name.frame ?? glyphBox(name)])
      for (const other of values)
        if (other !== box)
          expect(
            box.x + box.width <= other.x ||
              other.x + other.width <= box.x ||
              box.y + box.height <= other.y ||
              other.y + other.height <= box.y,
          ).toBe(true);
  });
});
