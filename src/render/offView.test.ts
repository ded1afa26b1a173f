import { describe, expect, it } from 'vitest';
import { glyphBox } from './labels';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/** A 600 × 400 figure of the unit square (fitted with no padding), labels held until placed. */
function unitSquare() {
  const view = new Viewport(600, 400);
  view.resize(600, 400);
  view.fit({ minX: 0, minY: 0, maxX: 1, maxY: 1 }, 0);
  const svg = new SvgContext();
  const painter = new Painter(svg, view, makeTheme(false, false));
  painter.holdLabels();
  return { view, painter, svg };
}

describe('a point the view leaves out', () => {
  it('on the figure: nothing is drawn', () => {
    const { painter, svg } = unitSquare();
    const empty = svg.toSvg(600, 400);
    expect(painter.offView([0.4, 0.6], 'P(t)', '#c00')).toBe(false);
    painter.placeLabels();
    expect(painter.labels).toEqual([]);
    expect(svg.toSvg(600, 400)).toBe(empty);
  });

  for (const [where, point, side] of [
    ['far above', [0.3, 5], 'top'],
    ['below and to the right', [4, -2], 'bottom right'],
    ['to the left', [-3, 0.5], 'left'],
  ] as const)
    it(`${where}: an arrow at that edge points at it, and is named`, () => {
      const { painter, view, svg } = unitSquare();
      expect(painter.offView(point, 'P(t)', '#c00')).toBe(true);
      painter.placeLabels();
      const [label] = painter.labels;
      expect(label.text).toBe('P(t)');
      const box = glyphBox(label);
      // The name is on the figure, whole.
      expect(box.x).toBeGreaterThanOrEqual(0);
      expect(box.y).toBeGreaterThanOrEqual(0);
      expect(box.x + box.width).toBeLessThanOrEqual(view.width);
      expect(box.y + box.height).toBeLessThanOrEqual(view.height);
      // The arrow's head (its filled tip) is near the edge towards the point,
      // on the line from the figure to it.
      const heads = [
        ...svg.toSvg(600, 400).matchAll(/d="M([\d.]+) ([\d.]+)L[^"]*Z?" fill="#c00"/g),
      ].map((m) => [Number(m[1]), Number(m[2])]);
      const edge = painter.theme.sizes.label * 1.5;
      const [px, py] = view.toScreen(point);
      const near = heads.some(([x, y]) => {
        if (side === 'top') return y <= edge && Math.abs(x - px) < 1;
        if (side === 'left') return x <= edge && Math.abs(y - py) < 1;
        return x >= 600 - edge && y >= 400 - edge;
      });
      expect(near, JSON.stringify(heads)).toBe(true);
    });
});
