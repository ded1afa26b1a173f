import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { glyphBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import type { SurfaceModel } from './model';
import { type SurfaceState, schema } from './state';
import { weightsFigure } from './weightsFigure';

// The heat map of fm(u)·fn(v) in the boxes it gets: presenter view's tall one
// beside the patch (860 × 840 px), and a phone's short, wide one under it (344 × 197 px,
// measured on the page at 360 × 740), where square cells 29 px a side could
// not hold "0.022" at the phone's least text size.
const model = lesson.derive(defaultsOf(schema) as SurfaceState) as SurfaceModel;

describe('the weights heat map', () => {
  // A 1366 × 768 projector's map (608 × 555 px) showed no number at all: its
  // edges kept room for handles it has not, and the cells (80 px) were too
  // small. Its type may be 0.85 of the least size (25 px there, 35 px were
  // it 1920 wide), as for every map.
  for (const [name, width, height, projector, floor] of [
    ['a phone', 344, 197, false, 1],
    ['presenter view', 860, 840, true, 1],
    ['a 1366 × 768 projector', 608, 555, true, 0.85],
  ] as const)
    it(`on ${name}: every number is inside its cell, clear of every line`, () => {
      const theme = makeTheme(false, projector);
      const { painter, view } = drawHeadless(weightsFigure, model, { width, height, theme });
      const numbers = painter.labels.filter((l) => /^0\.\d{3}$/.test(l.text));
      // 16 weights, 4 row factors and 4 column factors.
      expect(numbers).toHaveLength(24);
      for (const label of numbers) {
        expect(painter.ink.crossing(glyphBox(label)), `“${label.text}”`).toBeNull();
        expect(label.height / 1.3).toBeGreaterThanOrEqual(
          floor * (theme.sizes.minText ?? 12) - 1e-9,
        );
      }
      // The cells: never taller than wide, and at most 1.8 times as wide as tall.
      const [x0, y0] = view.toScreen([0, 0]);
      const [x1, y1] = view.toScreen([1, 1]);
      const ratio = Math.abs(x1 - x0) / Math.abs(y1 - y0);
      expect(ratio).toBeGreaterThanOrEqual(1 - 1e-9);
      expect(ratio).toBeLessThanOrEqual(1.8 + 1e-9);
    });

  it('too small for legible numbers (a phone’s map 90 px tall): colours only, no text at all', () => {
    // 90 px for 6.05 units: cells 15 px tall, room for numbers of 6.7 px, under the 12 px least.
    const theme = makeTheme(false, false);
    const { painter, svg } = drawHeadless(weightsFigure, model, { width: 344, height: 90, theme });
    expect(painter.labels).toEqual([]);
    expect(svg.toSvg(344, 90)).not.toContain('<text');
    // The 16 cells are still drawn, each filled by its weight.
    expect(svg.toSvg(344, 90).match(/<path[^>]*fill="[^"n]/g)?.length).toBeGreaterThanOrEqual(16);
  });
});
