import { describe, expect, it } from 'vitest';
import { drawInset } from './inset';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/**
 * A 1000 × 600 figure of [0, 10] × [0, 6]: 100 px a unit, so (x, y) is on
 * screen at (100x, 600 − 100y). The inset's side is 0.36 × 600 = 216 px
 * (rounded), a handle's radius (8 px, the screen theme's) from the edges: its
 * corners are at x 8 or 1000 − 216 − 8 = 776, y 8 or 600 − 216 − 8 = 376.
 */
function figure() {
  const view = new Viewport(1000, 600);
  view.fit({ minX: 0, minY: 0, maxX: 10, maxY: 6 }, 0);
  const svg = new SvgContext();
  const painter = new Painter(svg, view, makeTheme(false, false));
  return { svg, painter };
}

/** 0.2 × 0.1 around (5, 3): 20 × 10 px on screen, at (500, 300). */
const region = { minX: 4.9, minY: 2.95, maxX: 5.1, maxY: 3.05 };

describe('a magnified inset', () => {
  it('goes in the bottom right corner when all are free, the region filling 80% of it', () => {
    const { painter } = figure();
    let seen: number[][] = [];
    const box = drawInset(painter, { region }, (inset) => {
      seen = [inset.view.toScreen([5, 3]), inset.view.toScreen([5.1, 3])];
    });
    expect(box).toEqual({ x: 776, y: 376, width: 216, height: 216 });
    // The region's centre at the box's centre; magnified 0.8 × 216 / 20 = 8.64 times.
    expect(seen[0][0]).toBeCloseTo(776 + 108, 6);
    expect(seen[0][1]).toBeCloseTo(376 + 108, 6);
    expect(seen[1][0] - seen[0][0]).toBeCloseTo(10 * 8.64, 6);
  });

  it('says how much larger it is, rounded', () => {
    const { svg, painter } = figure();
    drawInset(painter, { region }, () => {});
    expect(svg.texts).toEqual(['×9']);
    // At most 12 times, however small the region.
    const tiny = { minX: 5, minY: 3, maxX: 5.001, maxY: 3.001 };
    const again = figure();
    drawInset(again.painter, { region: tiny }, () => {});
    expect(again.svg.texts).toEqual(['×12']);
  });

  it('leaves a handle uncovered, and takes the free corner with the least ink', () => {
    const { painter } = figure();
    // A handle at (9, 1), on screen (900, 500): in the bottom right corner.
    expect(drawInset(figure().painter, { region, avoid: [[9, 1]] }, () => {})).toMatchObject({
      x: 776,
      y: 8,
    });
    // A stroke from (800, 100) to (950, 50) through the top right one as well.
    painter.segment([8, 5], [9.5, 5.5], { width: 4 });
    expect(drawInset(painter, { region, avoid: [[9, 1]] }, () => {})).toMatchObject({
      x: 8,
      y: 376,
    });
  });

  it('is not drawn where every corner would cover a handle', () => {
    const { svg, painter } = figure();
    const corners = [
      [1, 1],
      [9, 1],
      [1, 5],
      [9, 5],
    ];
    const before = svg.elements.length;
    let drawn = false;
    expect(drawInset(painter, { region, avoid: corners }, () => (drawn = true))).toBeNull();
    expect(drawn).toBe(false);
    expect(svg.elements.length).toBe(before);
  });

  it('clips what it draws to its box, and no label may sit on it', () => {
    const { svg, painter } = figure();
    const box = drawInset(painter, { region }, (inset) =>
      inset.segment([0, 3], [10, 3], { width: 3 }),
    )!;
    const clip = svg.elements.find((e) => e.startsWith('<clipPath'))!;
    expect(clip).toContain('d="M776 376h216v216h-216Z"');
    const id = /id="([^"]+)"/.exec(clip)![1];
    // The one stroke, and the magnification's text, are drawn clipped.
    const clipped = svg.elements.filter((e) => e.includes(`clip-path="url(#${id})"`));
    expect(clipped.filter((e) => e.startsWith('<path')).length).toBe(1);
    expect(clipped.filter((e) => e.startsWith('<text')).length).toBeGreaterThan(0);
    // A label box in the middle of the inset, with no stroke under it, is still on ink.
    expect(painter.ink.crosses({ x: box.x + 20, y: box.y + 20, width: 30, height: 20 })).toBe(true);
    expect(painter.ink.crosses({ x: 300, y: 100, width: 30, height: 20 })).toBe(false);
  });
});
