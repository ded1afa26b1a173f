import { expect } from 'vitest';
import { drawHeadless } from '../src/app/headless';
import type { LessonDefinition } from '../src/app/lesson';
import { defaultsOf } from '../src/app/urlState';
import { makeTheme } from '../src/render/theme';

/** Whether two `drawnFrom` lists are the same, value by value (as the shell compares them). */
export const sameFrom = (a: readonly unknown[], b: readonly unknown[]) =>
  a.length === b.length && a.every((x, i) => Object.is(x, b[i]));

/**
 * A figure with `drawnFrom` is not drawn again while its list stays the same
 * (a slider's drag before the step that uses it): so the same list must give
 * the same picture. Draws figure `id` headless at every step of every scene,
 * at the two states `pair` makes of it, and fails where the lists agree and
 * the pictures do not (or, with `moves`, where the lists differ and the
 * pictures do not: then the value need not be in the list). Returns how many
 * steps the figure would skip and how many it would draw again.
 */
export function sameFromSamePicture<S extends { step: number }, M>(
  lesson: LessonDefinition<S, M>,
  id: string,
  pair: (state: S) => [S, S],
  moves = false,
): { skipped: number; used: number } {
  const figure = lesson.figures.find((f) => f.id === id)!;
  const theme = makeTheme(false, false);
  const drawn = (state: S) => {
    const model = lesson.derive(state);
    const { svg } = drawHeadless(figure, model, { width: 640, height: 480, theme });
    return { from: figure.drawnFrom!(model), svg: svg.toSvg(640, 480) };
  };
  let skipped = 0;
  let used = 0;
  for (const scene of lesson.scenes!) {
    const start = scene.apply(defaultsOf(lesson.schema) as S) as S;
    for (let step = 0; step <= lesson.steps!.count(start); step++) {
      const [a, b] = pair({ ...start, step }).map(drawn);
      if (sameFrom(a.from, b.from)) {
        skipped++;
        expect(b.svg, `${scene.id} step ${step}`).toBe(a.svg);
      } else {
        used++;
        if (moves) expect(b.svg, `${scene.id} step ${step}`).not.toBe(a.svg);
      }
    }
  }
  return { skipped, used };
}
