/**
 * For the lessons' unit tests: every scene of a lesson's script, at its first
 * and last step, drawn through the recording context (as tests/lessons.test.ts
 * does). Step 0 must draw less than the last step, and no scene may need more
 * than 20 presses of the clicker.
 */
import { expect } from 'vitest';
import type { AnyLesson } from '../../app/lesson';
import { normalizeState } from '../../app/lessonState';
import { defaultsOf } from '../../app/urlState';
import { Painter } from '../../render/painter';
import { SvgContext } from '../../render/svgContext';
import { makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';

/** Elements drawn by every figure of the lesson for this state. */
export function drawnElements(lesson: AnyLesson, state: unknown): number {
  const model = lesson.derive(state);
  let count = 0;
  for (const figure of lesson.figures) {
    const view = new Viewport();
    view.resize(900, 560);
    view.fit(figure.bounds(model), 40, figure.kind !== 'plot');
    const svg = new SvgContext();
    const painter = new Painter(svg, view, makeTheme(false, true));
    const info = { hover: null, thumbnail: false };
    figure.draw(painter, model, info);
    figure.drawOver?.(painter, model, info);
    count += svg.elements.length;
  }
  return count;
}

export function checkScript(lesson: AnyLesson): void {
  const steps = lesson.steps!;
  const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
  expect(lesson.scenes?.length).toBeGreaterThan(1);
  // The first scene is what the lesson opens with.
  expect(lesson.scenes![0].apply(defaults)).toEqual(defaults);
  for (const scene of lesson.scenes!) {
    const base = { ...scene.apply(defaults), [steps.key]: 0 };
    const first = normalizeState(lesson, base).state;
    const count = steps.count(first);
    expect(count, `${scene.id}: steps`).toBeLessThanOrEqual(20);
    expect(count, `${scene.id}: steps`).toBeGreaterThan(1);
    const last = normalizeState(lesson, { ...first, [steps.key]: count }).state;
    expect(drawnElements(lesson, first), `${scene.id}: step 0 draws less`).toBeLessThan(
      drawnElements(lesson, last),
    );
    for (let k = 0; k <= count; k++) {
      const at = { ...first, [steps.key]: k };
      const caption = steps.describe(at, k);
      expect(caption.length, `${scene.id} step ${k}`).toBeGreaterThan(3);
      // Words and Unicode: no TeX, no references to equations the app does not show.
      expect(caption, `${scene.id} step ${k}`).not.toMatch(/[\\_^{}]|[Ee]quation|the notes/);
      const formula = steps.formula?.(lesson.derive(at), at) ?? null;
      if (formula !== null)
        expect(formula, `${scene.id} step ${k}`).not.toMatch(/NaN|Infinity|\\val/);
    }
  }
}
