/**
 * The gallery as the page's content: every lesson's card, under the app's
 * own title. What the entry shows when no lesson is asked for, or one cannot
 * be opened.
 */
import { setChildren } from './dom';
import { buildGallery } from './gallery';
import { lessons } from './registry';

export function showGallery(main: HTMLElement, dark: boolean): void {
  document.title = 'Spline Lab';
  setChildren(main, buildGallery(lessons, dark));
}
