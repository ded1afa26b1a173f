import type { AnyLesson } from './lesson';
import { deCasteljau } from '../lessons/de-casteljau/lesson';

/** Every lesson, in course order. Adding a lesson: its folder, and one line here. */
export const lessons: AnyLesson[] = [deCasteljau];

export function findLesson(slug: string): AnyLesson | undefined {
  return lessons.find((l) => l.slug === slug);
}
