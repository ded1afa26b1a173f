/**
 * Checks every lesson's script must pass, for its unit tests (Vitest only).
 * The lesson opens with its first scene; each scene has 2 to 20 steps (the
 * clicker's presses); step 0 draws less than the last step (counted through
 * the recording context, as tests/lessons.test.ts draws, at desk and at
 * projector sizes); every caption is a sentence of plain words (no TeX, no
 * "Equation 7"); every step draws finite numbers; every step's formula has
 * its numbers filled in, finite and written as a reader writes them.
 */
import { expect } from 'vitest';
import { fitFigure } from '../app/headless';
import type { AnyLesson } from '../app/lesson';
import { normalizeState } from '../app/lessonState';
import { defaultsOf } from '../app/urlState';
import { Painter } from '../render/painter';
import { SvgContext } from '../render/svgContext';
import { makeTheme } from '../render/theme';
import { Viewport } from '../render/viewport';

/**
 * Drawing elements and texts of every figure of `lesson` at `state`, fitted
 * to the figure's bounds, in the light theme at desk sizes (or projector sizes).
 */
export function drawState(lesson: AnyLesson, state: unknown, { projector = false } = {}) {
  const model = lesson.derive(state);
  let elements = 0;
  const texts: string[] = [];
  const svg: string[] = [];
  for (const figure of lesson.figures) {
    const view = new Viewport();
    view.resize(900, 560);
    const theme = makeTheme(false, projector);
    fitFigure(view, figure, model, theme, 40);
    const context = new SvgContext();
    const painter = new Painter(context, view, theme);
    figure.draw(painter, model, { hover: null, thumbnail: false });
    figure.drawOver?.(painter, model, { hover: null, thumbnail: false });
    elements += context.elements.length;
    texts.push(...context.texts);
    svg.push(context.toSvg(900, 560));
  }
  return { elements, texts, svg: svg.join('\n') };
}

/** Every scene of the lesson as it opens (normalised, at step 0), and the state at its step k. */
export function sceneStates(lesson: AnyLesson) {
  const steps = lesson.steps!;
  const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
  return (lesson.scenes ?? []).map((scene) => {
    const opened = { ...scene.apply(defaults), [steps.key]: 0 };
    const base = normalizeState(lesson, opened).state as Record<string, unknown>;
    const count = steps.count(base);
    const at = (k: number) => ({ ...base, [steps.key]: k });
    return { id: scene.id, count, at };
  });
}

/** Runs every check of the script on `lesson` (see the top of this file). */
export function checkScript(lesson: AnyLesson): void {
  const steps = lesson.steps!;
  const scenes = sceneStates(lesson);
  expect(scenes.length, 'scenes').toBeGreaterThan(1);
  // The first scene is what the lesson opens with, at its step 0 (as the
  // shell opens every scene), so a lecturer's first press is the first step.
  const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
  expect(defaults[steps.key], 'the lesson opens at step 0').toBe(0);
  expect(
    { ...lesson.scenes![0].apply(defaults), [steps.key]: 0 },
    'the first scene is the defaults',
  ).toEqual(defaults);
  for (const { id, count, at } of scenes) {
    expect(count, `${id}: steps`).toBeGreaterThan(1);
    expect(count, `${id}: steps`).toBeLessThanOrEqual(20);
    for (const projector of [false, true]) {
      const first = drawState(lesson, at(0), { projector }).elements;
      const last = drawState(lesson, at(count), { projector }).elements;
      expect(first, `${id}: step 0 draws less than step ${count}`).toBeLessThan(last);
    }
    for (let k = 0; k <= count; k++) {
      const caption = steps.describe(at(k), k);
      expect(caption.length, `${id} step ${k} has a caption`).toBeGreaterThan(10);
      expect(caption, `${id} step ${k}: plain words`).not.toMatch(/[_\\{}^]|[Ee]quation|the notes/);
      expect(drawState(lesson, at(k)).svg, `${id} step ${k}`).not.toMatch(/NaN|Infinity/);
      // A formula may say in words (\text{…}) that a value is undefined; its
      // numbers may not be. `\val` is a live formula's slot left unfilled.
      const formula = (steps.formula?.(lesson.derive(at(k)), at(k)) ?? '').replace(
        /\\text\{[^}]*\}/g,
        '',
      );
      expect(formula, `${id} step ${k}: formula`).not.toMatch(
        /NaN|Infinity|undefined|\\val|\+ -|e[+-]\d/,
      );
    }
  }
}
