/**
 * The practice card's parts: its heading and Close, the prompt, the box for
 * the answer fields, Check, Show me and New numbers, the result (announced
 * politely), the list of exercises and the tally of what is solved on this
 * device. Practice (practice.ts) fills them and answers their buttons.
 */
import type { ExerciseSpec } from '../kit/exercise';
import { h } from './dom';
import { lessonProgress, readProgress } from './progress';

/** What the card's buttons do. */
export interface PracticeActions {
  check(): void;
  showMe(): void;
  newNumbers(): void;
  close(): void;
}

/** The card, and its parts that change as exercises come and go. */
export interface PracticeCard {
  element: HTMLElement;
  list: HTMLElement;
  prompt: HTMLElement;
  fields: HTMLElement;
  result: HTMLElement;
  tally: HTMLElement;
  showButton: HTMLButtonElement;
}

/** Builds the card, hidden until an exercise starts. */
export function practiceCard(actions: PracticeActions): PracticeCard {
  const list = h('div', { class: 'practice-list', role: 'group', 'aria-label': 'Exercises' });
  const prompt = h('p', { class: 'practice-prompt' });
  const fields = h('div', { class: 'practice-fields' });
  const result = h('p', { class: 'practice-result', role: 'status', 'aria-live': 'polite' });
  const tally = h('p', { class: 'practice-tally' });
  const showButton = h('button', { type: 'button', onclick: () => actions.showMe() }, 'Show me');
  const form = h(
    'form',
    {
      class: 'practice-form',
      onsubmit: (e: Event) => {
        e.preventDefault();
        actions.check();
      },
    },
    fields,
    h(
      'div',
      { class: 'practice-actions' },
      h('button', { type: 'submit', class: 'primary' }, 'Check'),
      showButton,
      h(
        'button',
        {
          type: 'button',
          title: 'The same exercise with numbers of your own',
          onclick: () => actions.newNumbers(),
        },
        'New numbers',
      ),
    ),
  );
  const element = h(
    'section',
    { class: 'practice', 'aria-label': 'Practice', hidden: true },
    h(
      'div',
      { class: 'practice-head' },
      h('h2', {}, 'Practice'),
      h(
        'button',
        { type: 'button', class: 'practice-close', onclick: () => actions.close() },
        'Close practice',
      ),
    ),
    prompt,
    h(
      'p',
      { class: 'practice-quiet-note' },
      'The lesson’s text is folded away until you have answered, or asked Show me: its numbers would give the answer away.',
    ),
    form,
    result,
    list,
    tally,
  );
  return { element, list, prompt, fields, result, tally, showButton };
}

/**
 * The lesson's exercises as buttons: the current one pressed, each one solved
 * on this device ticked. `pick` opens the one pressed.
 */
export function exerciseButtons<S>(
  slug: string,
  exercises: readonly ExerciseSpec<S>[],
  current: ExerciseSpec<S> | undefined,
  pick: (spec: ExerciseSpec<S>) => void,
): HTMLButtonElement[] {
  const progress = readProgress();
  return exercises.map((spec, i) => {
    const done = progress.exercises[`${slug}/${spec.id}`]?.done ?? false;
    return h(
      'button',
      {
        type: 'button',
        class: 'practice-pick',
        'aria-pressed': String(spec === current),
        'data-exercise': spec.id,
        onclick: () => pick(spec),
      },
      `${i + 1}. ${spec.title}`,
      done ? h('span', { class: 'practice-done', 'aria-label': ' (solved)' }, ' ✓') : null,
    );
  });
}

/** The tally: how many of the lesson's exercises are solved, and how the current one went. */
export function tallyText<S>(slug: string, current: ExerciseSpec<S> | undefined): string {
  const { done, total } = lessonProgress(slug);
  const mine = current ? readProgress().exercises[`${slug}/${current.id}`] : undefined;
  const here = mine
    ? mine.done
      ? ` This one is solved (${mine.tries} ${mine.tries === 1 ? 'check' : 'checks'}).`
      : ` ${mine.tries} ${mine.tries === 1 ? 'check' : 'checks'} on this one so far.`
    : '';
  return `Solved ${done} of ${total} in this lesson.${here}`;
}
