/**
 * Checks every lesson's script must pass, for its unit tests (Vitest only):
 * each scene's step count is at most 20, step 0 draws less than the last step
 * (counted through the recording context, as tests/lessons.test.ts draws),
 * every caption is plain words (no TeX), and every state of the script draws
 * finite numbers. Shared by the de Casteljau, Bézier-properties and quadratic
 * tests; it belongs next to tests/lessons.test.ts in the shell.
 */
import { expect } from 'vitest';
import type { AnyLesson } from '../../app/lesson';
import { normalizeState } from '../../app/lessonState';
import { defaultsOf } from '../../app/urlState';
import { Painter } from '../../render/painter';
import { SvgContext } from '../../render/svgContext';
import { makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';

/** Drawing elements and texts of every figure of `lesson` at `state`, fitted to the figure's bounds. */
export function drawState(lesson: AnyLesson, state: unknown) {
  const model = lesson.derive(state);
  let elements = 0;
  const texts: string[] = [];
  const svg: string[] = [];
  for (const figure of lesson.figures) {
    const view = new Viewport();
    view.resize(900, 560);
    view.fit(figure.bounds(model), 40, figure.kind !== 'plot');
    const context = new SvgContext();
    const painter = new Painter(context, view, makeTheme(false, false));
    figure.draw(painter, model, { hover: null, thumbnail: false });
    figure.drawOver?.(painter, model, { hover: null, thumbnail: false });
    elements += context.elements.length;
    texts.push(...context.texts);
    svg.push(context.toSvg(900, 560));
  }
  return { elements, texts, svg: svg.join('\n') };
}

/** Every scene of the lesson, at step `k` (clamped to its count) or at its last step. */
export function sceneStates(lesson: AnyLesson) {
  const steps = lesson.steps!;
  const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
  return (lesson.scenes ?? []).map((scene) => {
    const base = normalizeState(lesson, scene.apply(defaults)).state as Record<string, unknown>;
    const count = steps.count(base);
    const at = (k: number) => ({ ...base, [steps.key]: k });
    return { id: scene.id, count, at };
  });
}

export function checkScript(lesson: AnyLesson): void {
  const steps = lesson.steps!;
  const scenes = sceneStates(lesson);
  expect(scenes.length).toBeGreaterThan(0);
  for (const { id, count, at } of scenes) {
    expect(count, `${id}: steps`).toBeGreaterThan(0);
    expect(count, `${id}: steps`).toBeLessThanOrEqual(20);
    const first = drawState(lesson, at(0)).elements;
    const last = drawState(lesson, at(count)).elements;
    expect(first, `${id}: step 0 draws less than step ${count}`).toBeLessThan(last);
    for (let k = 0; k <= count; k++) {
      const caption = steps.describe(at(k), k);
      expect(caption.length, `${id} step ${k} has a caption`).toBeGreaterThan(10);
      expect(caption, `${id} step ${k}: plain words`).not.toMatch(/[_\\{}^]|Equation|the notes/);
      expect(drawState(lesson, at(k)).svg, `${id} step ${k}`).not.toMatch(/NaN|Infinity/);
      const formula = steps.formula?.(lesson.derive(at(k)), at(k)) ?? '';
      expect(formula, `${id} step ${k}: formula`).not.toMatch(
        /NaN|Infinity|undefined|\+ -|e[+-]\d/,
      );
    }
  }
}
