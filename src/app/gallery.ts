import { Painter } from '../render/painter';
import type { Theme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { h } from './dom';
import { type AnyLesson, GROUP_TITLES, type LessonGroup } from './lesson';
import { defaultsOf } from './urlState';

const ORDER: LessonGroup[] = ['interpolation', 'bezier', 'splines', 'surfaces'];

/** The home page: lessons grouped as the course chapter runs, each with a drawn thumbnail. */
export function buildGallery(lessons: readonly AnyLesson[], theme: Theme): HTMLElement {
  const sections = ORDER.filter((group) => lessons.some((l) => l.group === group)).map((group) =>
    h(
      'section',
      { class: 'gallery-group', 'aria-labelledby': `group-${group}` },
      h('h2', { id: `group-${group}` }, GROUP_TITLES[group]),
      h(
        'ul',
        { class: 'cards' },
        ...lessons
          .filter((l) => l.group === group)
          .map((lesson) => {
            const canvas = h('canvas', {
              class: 'thumb',
              'aria-hidden': 'true',
              width: 320,
              height: 180,
            });
            requestAnimationFrame(() => drawThumbnail(canvas, lesson, theme));
            return h(
              'li',
              {},
              h(
                'a',
                { class: 'card', href: `#/${lesson.slug}`, 'data-slug': lesson.slug },
                canvas,
                h('span', { class: 'card-title' }, lesson.title),
                h('span', { class: 'card-summary' }, lesson.summary),
              ),
            );
          }),
      ),
    ),
  );
  return h(
    'div',
    { class: 'gallery' },
    h(
      'header',
      { class: 'gallery-intro' },
      h('h1', {}, 'Spline Lab'),
      h(
        'p',
        {},
        'Interactive constructions for the splines chapter of a computer-graphics course. Drag the points, step through each construction, and share exactly what you see with a link.',
      ),
    ),
    ...sections,
  );
}

/** Draws the lesson's first figure at its default state, small. */
export function drawThumbnail(canvas: HTMLCanvasElement, lesson: AnyLesson, theme: Theme): void {
  const ctx = canvas.getContext('2d');
  if (!ctx) return;
  const dpr = window.devicePixelRatio || 1;
  const width = canvas.clientWidth || 320;
  const height = canvas.clientHeight || 180;
  canvas.width = Math.round(width * dpr);
  canvas.height = Math.round(height * dpr);
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  const figure = lesson.figures[0];
  const state = defaultsOf(lesson.schema);
  const view = new Viewport(width, height);
  view.fit(figure.bounds(state), 18, figure.kind === 'geometry');
  const small = {
    ...theme,
    sizes: { ...theme.sizes, curve: 2.5, line: 1.25, point: 3, handle: 4, label: 10, small: 9 },
  };
  const painter = new Painter(ctx, view, small);
  painter.clear();
  figure.draw(painter, state, { hover: null, thumbnail: true });
  for (const handle of figure.handles?.(state) ?? [])
    painter.handle(handle.position, { color: handle.color, radius: 3.5 });
}
