/**
 * Gallery thumbnails, drawn at build time (in Node, through Vite) by each
 * lesson's own first figure at its default state, as SVG: the gallery shows
 * them as images and loads no lesson code.
 */
import type { AnyLesson } from './lesson';
import { lessons } from './registry';
import { makeTheme } from '../render/theme';
import { drawHeadless } from './headless';
import { defaultsOf } from './urlState';

const WIDTH = 320;
const HEIGHT = 180;

/** One thumbnail as an SVG document. */
export function renderThumbnail(lesson: AnyLesson, dark: boolean): string {
  const base = makeTheme(dark, false);
  const theme = {
    ...base,
    sizes: {
      ...base.sizes,
      curve: 2.5,
      line: 1.25,
      point: 3,
      handle: 4,
      label: 10,
      small: 9,
      minText: 0,
    },
  };
  const state = lesson.normalize
    ? lesson.normalize(defaultsOf(lesson.schema)).state
    : defaultsOf(lesson.schema);
  const model = lesson.derive(state);
  const { svg } = drawHeadless(lesson.figures[0], model, {
    width: WIDTH,
    height: HEIGHT,
    theme,
    thumbnail: true,
  });
  return svg.toSvg(WIDTH, HEIGHT, theme.background);
}

/** Every lesson's thumbnails, light and dark, by file name (`<slug>-light.svg`). */
export async function renderThumbnails(): Promise<Record<string, string>> {
  const files: Record<string, string> = {};
  for (const meta of lessons) {
    const lesson = await meta.load();
    for (const dark of [false, true])
      files[`${meta.slug}-${dark ? 'dark' : 'light'}.svg`] = renderThumbnail(lesson, dark);
  }
  return files;
}
