import { h } from './dom';
import { GROUP_ORDER, GROUP_TITLES, type LessonMeta } from './meta';
import { lessonProgress, readProgress } from './progress';

/** "Practice: 2 of 3 solved", once the lesson's practice has been opened on this device. */
function practiceBadge(
  slug: string,
  progress: ReturnType<typeof readProgress>,
): HTMLElement | null {
  const { done, total } = lessonProgress(slug, progress);
  if (total === 0) return null;
  return h(
    'span',
    { class: `card-progress${done >= total ? ' complete' : ''}` },
    done >= total ? `Practice: all ${total} solved ✓` : `Practice: ${done} of ${total} solved`,
  );
}

/** The file a lesson's thumbnail is drawn to at build time (see scripts/plugins.ts). */
export const thumbnailPath = (slug: string, dark: boolean) =>
  `thumbnails/${slug}-${dark ? 'dark' : 'light'}.svg`;

/**
 * The home page: lessons grouped as the course chapter runs, each with a
 * thumbnail drawn at build time by the lesson's own figure code. It loads no
 * lesson code.
 */
export function buildGallery(lessons: readonly LessonMeta[], dark: boolean): HTMLElement {
  const progress = readProgress();
  const sections = GROUP_ORDER.filter((group) => lessons.some((l) => l.group === group)).map(
    (group) =>
      h(
        'section',
        { class: 'gallery-group', 'aria-labelledby': `group-${group}` },
        h('h2', { id: `group-${group}` }, GROUP_TITLES[group]),
        h(
          'ul',
          { class: 'cards' },
          ...lessons
            .filter((l) => l.group === group)
            .map((lesson) =>
              h(
                'li',
                {},
                h(
                  'a',
                  { class: 'card', href: `#/${lesson.slug}`, 'data-slug': lesson.slug },
                  h('img', {
                    class: 'thumb',
                    src: thumbnailPath(lesson.slug, dark),
                    alt: '',
                    width: 320,
                    height: 180,
                    decoding: 'async',
                  }),
                  h('span', { class: 'card-title' }, lesson.title),
                  h('span', { class: 'card-summary' }, lesson.summary),
                  practiceBadge(lesson.slug, progress),
                ),
              ),
            ),
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
        'Interactive constructions for the splines chapter of a computer-graphics course. Drag the points, step through each construction, practise with exercises the app checks, and share exactly what you see with a link.',
      ),
    ),
    ...sections,
  );
}
