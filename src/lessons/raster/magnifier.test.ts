import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { glyphBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import type { RasterModel } from './model';
import { type RasterState, schema } from './state';

const derive = (s: RasterState) => lesson.derive(s) as RasterModel;

describe('the magnified segment’s coverage shares', () => {
  it('each stands in its own pixel, at every step, on the projector, a laptop and a phone', () => {
    const scene = lesson.scenes!.find((s) => s.id === 'coverage')!;
    const base = scene.apply(defaultsOf(schema));
    const figure = lesson.figures.find((f) => f.id === 'side')!;
    let checked = 0;
    for (let step = 0; step <= lesson.steps!.count(base); step++)
      for (const [width, height, presenter] of [
        [850, 900, true],
        // A 1366 × 768 projector's side figure.
        [594, 580, true],
        [400, 600, false],
        [344, 230, false],
      ] as const) {
        const m = derive({ ...base, step });
        const { painter, view } = drawHeadless(figure, m, {
          width,
          height,
          theme: makeTheme(false, presenter),
        });
        const cellOf = (l: { x: number; y: number; width: number; height: number }) =>
          view.toWorld([l.x + l.width / 2, l.y + l.height / 2]);
        for (const { i, j, value } of m.segmentCoverage ?? []) {
          const text = value.toFixed(2);
          const labels = painter.labels.filter((l) => l.text === text);
          if (labels.length === 0) continue;
          checked++;
          // One of the labels that read its share has its middle, taken back
          // to the raster's units, in pixel (i, j): within ½ of it each way.
          const inside = labels.some((l) => {
            const [x, y] = cellOf(l);
            return Math.abs(x - i) < 0.5 && Math.abs(y - j) < 0.5;
          });
          expect(
            inside,
            `step ${step} at ${width} × ${height}: ${text} of pixel (${i}, ${j})`,
          ).toBe(true);
        }
        // No share covers another: each (its box, if boxed) stays inside its
        // pixel, whose side on screen is 1 raster unit.
        const side = 1 / view.worldLength(1);
        const shares = painter.labels.filter((l) => /^\d\.\d\d$/.test(l.text));
        for (const l of shares) {
          const box = l.frame ?? glyphBox(l);
          expect(box.width, `step ${step} at ${width} × ${height}: ${l.text}`).toBeLessThan(side);
          expect(box.height, `step ${step} at ${width} × ${height}: ${l.text}`).toBeLessThan(side);
        }
      }
    expect(checked).toBeGreaterThan(10);
  });
});
