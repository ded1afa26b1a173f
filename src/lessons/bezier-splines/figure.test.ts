import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import { type BezierSplinesState, schema } from './state';

// The view is fitted once, when a scene opens, and kept through its steps:
// what a later step draws must be inside the view its first step was fitted to.
describe('the continuity inspector', () => {
  const figure = lesson.figures.find((f) => f.id === 'main')!;
  const theme = makeTheme(false, true);
  const opened = lesson
    .scenes!.find((s) => s.id === 'inspector')!
    .apply(defaultsOf(schema) as BezierSplinesState) as BezierSplinesState;
  const last = lesson.steps!.count(opened);

  it('keeps the whole curvature comb of its last step in the view its first step is fitted to', () => {
    // Presenter view's figure at 1920 × 1080 (the caption above it) and a phone's.
    for (const [width, height] of [
      [1904, 820],
      [344, 300],
    ]) {
      const first = drawHeadless(figure, lesson.derive({ ...opened, step: 0 }), {
        width,
        height,
        theme,
      });
      const model = lesson.derive({ ...opened, step: last });
      expect(model.shown.has('comb')).toBe(true);
      for (const [, tip] of model.comb) {
        const [x, y] = first.view.toScreen(tip);
        expect(x, `${width}: tip at x`).toBeGreaterThanOrEqual(0);
        expect(x, `${width}: tip at x`).toBeLessThanOrEqual(width);
        expect(y, `${width}: tip at y`).toBeGreaterThanOrEqual(0);
        expect(y, `${width}: tip at y`).toBeLessThanOrEqual(height);
      }
    }
  });
});

// A curve kept faint for comparison is named: in "C¹ and C² by hand" the C¹
// spline stays behind the C² one, and unnamed, beside "they agree to 12
// digits", it read as the C² spline's second curve.
describe('the faint curves kept for comparison', () => {
  const figure = lesson.figures.find((f) => f.id === 'main')!;
  const theme = makeTheme(false, true);
  // (Degree d's earlier degrees are named together at the step after, the
  // step that is for that: workedScript.test.)
  for (const [scene, names] of [['worked', ['C¹ spline']]] as const)
    it(`${scene}: each is named at the scene's last step`, () => {
      const opened = lesson
        .scenes!.find((s) => s.id === scene)!
        .apply(defaultsOf(schema) as BezierSplinesState) as BezierSplinesState;
      const model = lesson.derive({ ...opened, step: lesson.steps!.count(opened) });
      const { painter, svg } = drawHeadless(figure, model, { width: 1348, height: 560, theme });
      // The faint strokes are there, and each is named.
      expect(svg.elements.some((e) => e.includes(theme.curveFaint))).toBe(true);
      const texts = painter.labels.map((l) => l.text);
      for (const name of names) expect(texts, name).toContain(name);
    });
});
