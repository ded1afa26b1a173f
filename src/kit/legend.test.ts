import { describe, expect, it } from 'vitest';
import { Painter } from '../render/painter';
import { SvgContext } from '../render/svgContext';
import { makeTheme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { drawLegend } from './legend';

function legendSvg(labels: boolean): string[] {
  const svg = new SvgContext();
  const view = new Viewport(400, 300);
  view.resize(400, 300);
  view.fit({ minX: 0, minY: 0, maxX: 1, maxY: 1 }, 10);
  const painter = new Painter(svg, view, makeTheme(false, false), {
    curve: true,
    labels,
    numbers: true,
  });
  drawLegend(painter, [
    { text: 'Lagrange', line: { color: '#0072B2' } },
    { text: 'spline', line: { color: '#009E73', dash: [6, 4] } },
  ]);
  return svg.elements;
}

describe('a figure key', () => {
  it('draws a box, a line sample and a name per entry', () => {
    const drawn = legendSvg(true);
    expect(drawn.some((e) => e.startsWith('<rect'))).toBe(true);
    expect(drawn.filter((e) => />Lagrange<|>spline</.test(e)).length).toBeGreaterThanOrEqual(2);
  });
  it('with the labels hidden draws nothing: no empty box and nameless samples', () => {
    expect(legendSvg(false)).toEqual([]);
  });
});
