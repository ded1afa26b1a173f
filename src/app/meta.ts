/**
 * What the gallery knows of a lesson without loading it: its title, summary,
 * place in the course, and how to load the rest. Each lesson folder has a
 * `meta.ts` whose default export is one of these; the registry finds them all.
 */
import type { AnyLesson } from './lesson';

export type LessonGroup = 'interpolation' | 'bezier' | 'splines' | 'surfaces';

export const GROUP_TITLES: Record<LessonGroup, string> = {
  interpolation: 'Interpolation: a curve through points',
  bezier: 'Bézier curves',
  splines: 'Splines',
  surfaces: 'Surfaces and drawing',
};

export const GROUP_ORDER: readonly LessonGroup[] = [
  'interpolation',
  'bezier',
  'splines',
  'surfaces',
];

export interface LessonMeta {
  slug: string;
  title: string;
  /** One line for the gallery. */
  summary: string;
  group: LessonGroup;
  /** Place within the group, in course order (lower first). */
  order: number;
  /** Loads the lesson's own code (its chunk). */
  load(): Promise<AnyLesson>;
}

export function defineMeta(meta: LessonMeta): LessonMeta {
  return meta;
}
