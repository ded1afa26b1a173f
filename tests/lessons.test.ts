/**
 * Every lesson in the registry (no list kept by hand), drawn through the
 * recording context: at its defaults and at every preset, each figure draws
 * something, with no NaN or Infinity reaching the drawing, and every handle
 * sits at a finite position. What is drawn, not pixels.
 */
import { describe, expect, it } from 'vitest';
import type { AnyLesson } from '../src/app/lesson';
import { normalizeState } from '../src/app/lessonState';
import { lessons } from '../src/app/registry';
import { defaultsOf } from '../src/app/urlState';
import { drawHeadless } from '../src/app/headless';
import { makeTheme } from '../src/render/theme';

const WIDTH = 900;
const HEIGHT = 560;

function drawAll(lesson: AnyLesson, state: unknown, presenter = true) {
  const model = lesson.derive(state);
  const theme = makeTheme(false, presenter);
  return lesson.figures.map((figure) => {
    const height = figure.height ?? HEIGHT;
    const { svg, handles } = drawHeadless(figure, model, { width: WIDTH, height, theme });
    return {
      id: figure.id,
      svg: svg.toSvg(WIDTH, height),
      elements: svg.elements.length,
      handles,
      width: WIDTH,
      height,
    };
  });
}

describe('every lesson draws what it says', () => {
  it('the registry finds every lesson folder with a meta.ts', () => {
    expect(lessons.length).toBeGreaterThan(0);
    expect(new Set(lessons.map((l) => l.slug)).size).toBe(lessons.length);
  });

  for (const meta of lessons) {
    it(`${meta.slug}: defaults and every preset draw finite figures`, async () => {
      const lesson = await meta.load();
      expect(lesson.slug).toBe(meta.slug);
      const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
      const states = [
        ['defaults', defaults],
        ...(lesson.scenes ?? []).map((p) => [
          `preset ${p.id}`,
          normalizeState(lesson, p.apply(defaults)).state,
        ]),
      ] as const;
      for (const [name, state] of states) {
        for (const figure of drawAll(lesson, state)) {
          const where = `${meta.slug} ${name}, figure ${figure.id}`;
          expect(figure.elements, `${where} draws something`).toBeGreaterThan(1);
          expect(figure.svg, `${where} has no NaN`).not.toMatch(/NaN|Infinity/);
          for (const handle of figure.handles)
            expect(handle.position.every(Number.isFinite), `${where} ${handle.id}`).toBe(true);
        }
      }
    });
  }

  for (const meta of lessons) {
    it(`${meta.slug}: a script of scenes, each stepped from little to all`, async () => {
      const lesson = await meta.load();
      expect(lesson.steps, `${meta.slug} has steps`).toBeDefined();
      expect(lesson.scenes?.length ?? 0, `${meta.slug} has scenes`).toBeGreaterThan(0);
      const steps = lesson.steps!;
      const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
      // Every lesson opens at its first scene's step 0: the first press is the first step (#19).
      expect(defaults[steps.key], `${meta.slug} opens at step 0`).toBe(0);
      for (const scene of lesson.scenes!) {
        const opened = normalizeState(lesson, { ...scene.apply(defaults), [steps.key]: 0 }).state;
        const count = steps.count(opened);
        const where = `${meta.slug} scene ${scene.id}`;
        expect(count, `${where} has steps`).toBeGreaterThan(0);
        expect(count, `${where} steps in chunks`).toBeLessThanOrEqual(20);
        const size = (k: number) =>
          drawAll(lesson, { ...opened, [steps.key]: k }).reduce((n, f) => n + f.elements, 0);
        expect(size(0), `${where}: step 0 draws less than the last step`).toBeLessThan(size(count));
        for (let k = 0; k <= count; k++) {
          const caption = steps.describe({ ...opened, [steps.key]: k }, k);
          expect(caption.trim(), `${where} step ${k} has a caption`).not.toBe('');
          // Captions are read from the back of the room: words, not TeX or references.
          expect(caption, `${where} step ${k}`).not.toMatch(
            /\\[a-z]|_\{|\^\{|[Ee]quation \d|the notes/,
          );
        }
      }
    });
  }
});
