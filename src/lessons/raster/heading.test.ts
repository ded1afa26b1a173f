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
import type { RasterState } from './state';

const curve = lesson.figures.find((f) => f.id === 'curve')!;
const HEADING = /^Uniform/;

describe('the curve figure’s heading', () => {
  for (const [width, height, projector] of [
    [342, 205, false],
    [316, 200, false],
    [300, 190, false],
    [700, 420, false],
    [1880, 560, true],
  ] as const)
    it(`stands clear above the curve, unboxed, at ${width} × ${height}`, () => {
      const scenes = sceneStates(lesson).filter((s) => s.id === 'compare');
      expect(scenes.length).toBe(1);
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
