import { h, setDisabled } from './dom';
import type { LessonApi } from './lesson';

/** What a control needs of the lesson: the state, and a way to change it. */
export type StateApi<S> = Pick<LessonApi<S, unknown>, 'get' | 'set'>;

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
export function pointButtons<S>(api: StateApi<S>, options: PointButtonsOptions<S>): Control<S> {
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
      setDisabled(add, options.count(state) >= options.max);
      setDisabled(remove, options.count(state) <= options.min);
    },
  };
}

export interface CheckboxOptions<S> {
  id: string;
  label: string | Node;
  get(state: S): boolean;
  set(state: S, on: boolean): S;
}

/** A labelled checkbox bound to a yes/no of the state. */
export function checkbox<S>(api: StateApi<S>, options: CheckboxOptions<S>): Control<S> {
  const input = h('input', { type: 'checkbox', id: options.id });
  input.addEventListener('change', () => api.set(options.set(api.get(), input.checked)));
  return {
    element: h('label', { class: 'toggle', for: options.id }, input, options.label),
    update(state) {
      input.checked = options.get(state);
    },
  };
}

export interface RadioOptions<S, V extends string> {
  /** The group's name, also the prefix of each input's id. */
  name: string;
  choices: readonly { value: V; label: string | Node }[];
  get(state: S): V;
  set(state: S, value: V): S;
}

/** Radio buttons for one choice of the state, each on a labelled line. */
export function radioGroup<S, V extends string>(
  api: StateApi<S>,
  options: RadioOptions<S, V>,
): { labels: HTMLElement[]; update(state: S): void } {
  const inputs = options.choices.map(({ value }) => {
    const input = h('input', {
      type: 'radio',
      name: options.name,
      value,
      id: `${options.name}-${value}`,
    });
    input.addEventListener('change', () => {
      if (input.checked) api.set(options.set(api.get(), value));
    });
    return input;
  });
  return {
    labels: options.choices.map(({ value, label }, i) =>
      h('label', { class: 'toggle', for: `${options.name}-${value}` }, inputs[i], label),
    ),
    update(state) {
      const current = options.get(state);
      options.choices.forEach(({ value }, i) => (inputs[i].checked = value === current));
    },
  };
}
