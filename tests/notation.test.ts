/**
 * The parameter's letter is the reader's (μ, u or t): every caption, formula
 * and figure label of every step of every scene of a lesson that writes a
 * curve parameter, drawn in each of the three letters, shows that letter and
 * no other, and every formula still typesets.
 */
import katex from 'katex';
import { afterAll, describe, expect, it } from 'vitest';
import type { AnyLesson } from '../src/app/lesson';
import { normalizeState } from '../src/app/lessonState';
import { lessons } from '../src/app/registry';
import { defaultsOf } from '../src/app/urlState';
import { drawHeadless } from '../src/app/headless';
import { makeTheme } from '../src/render/theme';
import {
  DEFAULT_LETTER,
  LETTERS,
  type Letter,
  renamePlain,
  renameTex,
  say,
  sayTex,
  setNotation,
} from '../src/render/notation';

/** Does plain text or TeX write the letter `letter` as a symbol? (Renaming it would change something.) */
const writesPlain = (text: string, letter: Letter) =>
  renamePlain(text, letter, letter === 't' ? 'u' : 't') !== text;
const writesTex = (tex: string, letter: Letter) =>
  renameTex(tex, letter, letter === 't' ? 'u' : 't') !== tex;

const theme = makeTheme(false, true);

/** The texts of a figure's drawing: its labels. */
function figureTexts(lesson: AnyLesson, state: unknown): string[] {
  const model = lesson.derive(state);
  const shown = lesson.figuresShown?.(state) ?? null;
  return lesson.figures
    .filter((figure) => !shown || shown.includes(figure.id))
    .flatMap((figure) => {
      const { svg } = drawHeadless(figure, model, { width: 900, height: 560, theme });
      return [...svg.toSvg(900, 560).matchAll(/<text[^>]*>([^<]*)<\/text>/g)].map((m) =>
        m[1].replace(/&amp;/g, '&').replace(/&lt;/g, '<').replace(/&gt;/g, '>'),
      );
    });
}

describe('the parameter is written in the reader’s letter', () => {
  afterAll(() => setNotation(null, DEFAULT_LETTER));

  for (const meta of lessons) {
    it(`${meta.slug}: every step of every scene, in μ, u and t`, async () => {
      const lesson = await meta.load();
      // A lesson of its own letters (the surface's u and v, the road's p) is
      // drawn once, as it writes them: its formulas must still typeset.
      const own = lesson.letter ?? null;
      const steps = lesson.steps!;
      const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
      const found: string[] = [];
      for (const reader of own ? LETTERS : [DEFAULT_LETTER]) {
        setNotation(own, reader);
        const others = own ? LETTERS.filter((l) => l !== reader) : [];
        for (const scene of lesson.scenes ?? []) {
          const opened = normalizeState(lesson, { ...scene.apply(defaults), [steps.key]: 0 }).state;
          const count = steps.count(opened);
          for (let k = 0; k <= count; k++) {
            const state = normalizeState(lesson, { ...opened, [steps.key]: k }).state;
            const where = `${reader}: ${scene.id} step ${k}`;
            const caption = say(steps.describe(state, k));
            const formula = steps.formula?.(lesson.derive(state), state);
            const tex = formula ? sayTex(formula) : null;
            for (const other of others) {
              if (writesPlain(caption, other))
                found.push(`${where} caption “${caption}” has ${other}`);
              if (tex && writesTex(tex, other)) found.push(`${where} formula ${tex} has ${other}`);
            }
            if (tex)
              expect(
                () => katex.renderToString(tex, { throwOnError: true, strict: false, trust: true }),
                `${where} ${tex}`,
              ).not.toThrow();
            if (k === count || k === 0)
              for (const text of figureTexts(lesson, state))
                for (const other of others)
                  if (writesPlain(text, other)) found.push(`${where} label “${text}” has ${other}`);
          }
        }
      }
      expect(found).toEqual([]);
    }, 60_000);
  }
});
