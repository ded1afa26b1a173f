import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import { type HermiteState, schema } from './state';

// "Several points, by hand", last step: at μ = 0.3 on the second patch, P(μ) =
// (2.963, 2.018) lies on the tip of D₁ (P₁ + D₁/3 = (3, 2)). The handle there
// must not hide it.
describe('P(μ) on a gradient tip', () => {
  it('is drawn over the handle, not under it', () => {
    const figure = lesson.figures.find((f) => f.id === 'patches')!;
    const scene = lesson.scenes!.find((s) => s.id === 'several')!;
    const start = scene.apply(defaultsOf(schema) as HermiteState) as HermiteState;
    const model = lesson.derive({ ...start, step: lesson.steps!.count(start) });
    expect(model.patch.point[0]).toBeCloseTo(2.963, 3);
    expect(model.patch.point[1]).toBeCloseTo(2.018, 3);
    const theme = makeTheme(false, true);
    const { svg, view } = drawHeadless(figure, model, { width: 1880, height: 500, theme });
    const [x, y] = view.toScreen(model.patch.point);
    const elements = svg.toSvg(1880, 500).split('><');
    const dot = elements.map((e) => e.includes(`fill="${theme.accent}"`)).lastIndexOf(true);
    expect(dot).toBeGreaterThan(0);
    // Nothing that starts within a handle's reach of the point is drawn after it.
    const reach = theme.sizes.handle * 2;
    const after = elements.slice(dot + 1).filter((e) => {
      const start = /d="M(-?[\d.]+) (-?[\d.]+)/.exec(e);
      return start && Math.hypot(Number(start[1]) - x, Number(start[2]) - y) < reach;
    });
    expect(after).toEqual([]);
  });
});
