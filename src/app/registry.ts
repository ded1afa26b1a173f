import { GROUP_ORDER, type LessonMeta } from './meta';

// Every lesson folder's meta.ts, found at build time: a new lesson is its
// folder, nothing more. The metadata is tiny; each lesson's code is its own
// chunk, loaded when the lesson is opened.
const found = import.meta.glob<LessonMeta>('../lessons/*/meta.ts', {
  eager: true,
  import: 'default',
});

/** Every lesson, in course order: by group, then by order within it. */
export const lessons: LessonMeta[] = Object.values(found).sort(
  (a, b) => GROUP_ORDER.indexOf(a.group) - GROUP_ORDER.indexOf(b.group) || a.order - b.order,
);

export function findLesson(slug: string): LessonMeta | undefined {
  return lessons.find((l) => l.slug === slug);
}
