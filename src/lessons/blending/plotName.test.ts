import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import { type BlendingState, schema } from './state';

// Beside another basis the plot shows two families, Bernstein's solid and the
// other's dashed: under "W(N, i, μ)" alone, B₀ … B₃ read as Bernstein's.
describe('the plot’s y name', () => {
  const figure = lesson.figures.find((f) => f.id === 'blending')!;
  const nameAt = (scene: string, step?: number) => {
    const opened = lesson
      .scenes!.find((s) => s.id === scene)!
      .apply(defaultsOf(schema) as BlendingState) as BlendingState;
    const state = { ...opened, step: step ?? lesson.steps!.count(opened) };
    const { painter } = drawHeadless(figure, lesson.derive(state), {
      width: 660,
      height: 560,
      theme: makeTheme(false, true),
    });
    return painter.labels.map((l) => l.text).find((t) => t.startsWith('W(N, i, μ)'));
  };

  it('names both families where two are drawn, Bernstein’s alone before', () => {
    expect(nameAt('bspline')).toBe('W(N, i, μ) and B_{i}(μ)');
    expect(nameAt('hermite')).toBe('W(N, i, μ) and H_{i}(μ)');
    expect(nameAt('lagrange')).toBe('W(N, i, μ) and L_{i}(μ)');
    expect(nameAt('cubic')).toBe('W(N, i, μ)');
  });
});
