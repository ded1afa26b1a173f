import type { AnyLesson } from './lesson';
import { deCasteljau } from '../lessons/de-casteljau/lesson';
import { blending } from '../lessons/blending/lesson';
import { bezierProperties } from '../lessons/bezier-properties/lesson';
import { quadratic } from '../lessons/quadratic/lesson';
import { lagrange } from '../lessons/lagrange/lesson';
import { hermite } from '../lessons/hermite/lesson';
import { road } from '../lessons/road/lesson';

/** Every lesson, in course order. Adding a lesson: its folder, and one line here. */
export const lessons: AnyLesson[] = [
  quadratic,
  lagrange,
  hermite,
  deCasteljau,
  blending,
  bezierProperties,
  road,
];

export function findLesson(slug: string): AnyLesson | undefined {
  return lessons.find((l) => l.slug === slug);
}
