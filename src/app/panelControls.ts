import { h } from './dom';
import type { LessonApi } from './lesson';

/**
 * Controls that side panels share: each is bound to the lesson state through
 * the api, and returns its element with an `update` that shows the state.
 */
export interface Control<S> {
  element: HTMLElement;
  update(state: S): void;
}

export interface PointButtonsOptions<S> {
  addLabel: string;
  removeLabel: string;
  count(state: S): number;
  min: number;
  max: number;
  add(state: S): S;
  remove(state: S): S;
}

/** "Add a point" / "Remove the last point": the keyboard's way to change how many points there are. */
export function pointButtons<S>(api: LessonApi<S>, options: PointButtonsOptions<S>): Control<S> {
  const add = h('button', { type: 'button' }, options.addLabel);
  const remove = h('button', { type: 'button' }, options.removeLabel);
  add.addEventListener('click', () => {
    const s = api.get();
    if (options.count(s) < options.max) api.set(options.add(s));
  });
  remove.addEventListener('click', () => {
    const s = api.get();
    if (options.count(s) > options.min) api.set(options.remove(s));
  });
  return {
    element: h('div', { class: 'lesson-tools' }, add, remove),
    update(state) {
      add.disabled = options.count(state) >= options.max;
      remove.disabled = options.count(state) <= options.min;
    },
  };
}
