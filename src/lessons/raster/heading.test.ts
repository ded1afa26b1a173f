/**
 * The comparison's heading ("Uniform, planned: 14 segments") has a band of
 * its own above the curve: on a phone, with the handles at the figure's top,
 * it was boxed over the curve by P₆. Every step of the scene, at a phone's,
 * a laptop's and the projector's size, drawn as the page draws it.
 */
import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { glyphBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import { sceneStates } from '../../kit/scriptChecks';
import lesson from './lesson';
import { windowOf } from './raster';
import type { RasterState } from './state';

const curve = lesson.figures.find((f) => f.id === 'curve')!;
const HEADING = /^(Uniform|The box)/;

describe('the curve figure’s heading', () => {
  for (const [width, height, projector] of [
    [342, 205, false],
    [316, 200, false],
    [300, 190, false],
    [700, 420, false],
    [1880, 560, true],
  ] as const)
    it(`stands clear above the curve, unboxed, at ${width} × ${height}`, () => {
      const scenes = sceneStates(lesson).filter((s) => s.id === 'compare' || s.id === 'zoom');
      expect(scenes.length).toBe(2);
      for (const scene of scenes)
        for (let k = 0; k <= scene.count; k++) {
          const model = lesson.derive(scene.at(k) as unknown as RasterState);
          const { painter } = drawHeadless(curve, model, {
            width,
            height,
            theme: makeTheme(false, projector),
          });
          const where = `${scene.id} step ${k}`;
          const headings = painter.labels.filter((b) => HEADING.test(b.text));
          expect(headings.length, where).toBeGreaterThan(0);
          for (const b of headings) {
            expect(b.boxed ?? false, `${where}: “${b.text}” boxed`).toBe(false);
            expect(painter.ink.crossing(glyphBox(b)), `${where}: “${b.text}”`).toBeNull();
          }
        }
    });
});

describe('the zoom scene’s box', () => {
  it('is on the figure at every zoom, ×½ too, where it is twice the raster’s size', () => {
    const [scene] = sceneStates(lesson).filter((s) => s.id === 'zoom');
    for (let k = 0; k <= scene.count; k++) {
      const model = lesson.derive(scene.at(k) as unknown as RasterState);
      const { view } = drawHeadless(curve, model, {
        width: 342,
        height: 205,
        theme: makeTheme(false, false),
      });
      const box = windowOf(model.zoom!.size);
      for (const corner of [
        [box.minX, box.minY],
        [box.maxX, box.maxY],
      ]) {
        const [x, y] = view.toScreen(corner);
        expect(x >= 0 && x <= 342 && y >= 0 && y <= 205, `step ${k}: ${corner} at ${x}, ${y}`).toBe(
          true,
        );
      }
    }
  });
});
