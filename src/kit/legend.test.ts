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

describe('where a key goes', () => {
  /** A 600 × 400 figure of the unit square with a stroke through `corners`; the key's box. */
  function keyBox(corners: readonly ('top left' | 'top right')[]) {
    const view = new Viewport(600, 400);
    view.resize(600, 400);
    view.fit({ minX: 0, minY: 0, maxX: 1, maxY: 1 }, 0);
    const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
    painter.holdLabels();
    drawLegend(painter, [{ text: 'Lagrange polynomial', line: { color: '#0072B2' } }]);
    // A spike drawn after the key is called for, as a curve is: up through the corner's half.
    for (const corner of corners) {
      const x = corner === 'top left' ? 0.05 : 0.95;
      painter.polyline(
        [
          [x, 0.5],
          [x, 1],
        ],
        { width: 3 },
      );
    }
    painter.placeLabels();
    return painter.labels.find((b) => b.text === 'legend')!;
  }
  it('sits in the top left corner when nothing is drawn there', () => {
    const box = keyBox([]);
    expect(box.x).toBeLessThan(20);
    expect(box.y).toBeLessThan(20);
  });
  it('moves to the top right when a curve runs up through the top left', () => {
    const box = keyBox(['top left']);
    expect(box.x + box.width).toBeGreaterThan(580);
    expect(box.y).toBeLessThan(20);
  });
  it('goes to the foot when curves run through both top corners', () => {
    const box = keyBox(['top left', 'top right']);
    expect(box.x).toBeLessThan(20);
    expect(box.y + box.height).toBeGreaterThan(380);
  });
});
