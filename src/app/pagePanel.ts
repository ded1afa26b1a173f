/**
 * The lesson's side panel as the page shows it: made from the lesson's
 * definition, kept out of sight until its first update, and fitted again when
 * the sizes round it change.
 */
import { refitAll } from '../render/fit';
import type { AnyLesson, LessonApi, LessonPanel } from './lesson';

export class PagePanel<S, M> {
  private readonly panel: LessonPanel<S, M>;
  /**
   * The panel has not been updated yet: it is kept out of sight (and out of the
   * accessibility tree) so its first frame shows no control of another scene.
   */
  private pending = true;

  constructor(lesson: AnyLesson, api: LessonApi<S, M>) {
    this.panel = lesson.panel(api) as LessonPanel<S, M>;
    this.panel.element.classList.add('panel-pending');
  }

  get element(): HTMLElement {
    return this.panel.element;
  }

  /** The panel for a state just drawn; the first one also shows it. */
  update(model: M, state: S): void {
    this.panel.update(model, state);
    if (this.pending) {
      this.pending = false;
      this.panel.element.classList.remove('panel-pending');
    }
  }

  /** The hovered point changed: the panel marks it too (if it marks any). */
  hover(id: string | null): void {
    this.panel.hover?.(id);
  }

  /** Every formula and table is fitted to its box again (fonts arrived, sizes changed). */
  refit(): void {
    refitAll(this.panel.element);
  }

  destroy(): void {
    this.panel.destroy?.();
  }
}
