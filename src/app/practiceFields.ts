/**
 * The answer fields of an exercise: one text field for each number asked for,
 * x and y for a point (a tap on the figure fills them too), none for a
 * construction, under a line that says what to do. A typed number may use a
 * minus sign or a decimal comma.
 */
import type { Task } from '../kit/exercise';
import { h } from './dom';

/** Reads a typed number: a minus sign or a decimal comma is accepted. */
export function readNumber(text: string): number {
  const cleaned = text.trim().replace(/[−–]/g, '-').replace(',', '.');
  return cleaned === '' ? NaN : Number(cleaned);
}

/** Where a guess at a point is placed: the figure's title, and whether a tap places it. */
export interface GuessPlace {
  figureTitle(id: string): string;
  tappable(id: string): boolean;
}

/**
 * The fields of `task` and the line of help above them. `typed` is called as
 * x or y of a guessed point is typed.
 */
export function answerFields<S>(
  task: Task<S>,
  place: GuessPlace,
  typed: () => void,
): { help: string; rows: HTMLLabelElement[] } {
  const input = (label: string, i: number) => {
    const el = h('input', {
      type: 'text',
      inputmode: 'decimal',
      autocomplete: 'off',
      spellcheck: 'false',
      'data-field': i,
    });
    if (task.kind === 'point') el.addEventListener('input', () => typed());
    return h('label', { class: 'practice-field' }, h('span', {}, label), el);
  };
  let help: string;
  let labels: readonly string[];
  if (task.kind === 'number') {
    labels = task.fields;
    help = `Work it out, type ${labels.length === 1 ? 'it' : 'each number'}, then Check.`;
  } else if (task.kind === 'point') {
    labels = ['x', 'y'];
    help = place.tappable(task.figure)
      ? `Tap ${place.figureTitle(task.figure)} where you think it is (or type x and y), then Check.`
      : `Type x and y of your guess, then Check: it is marked on ${place.figureTitle(task.figure)}.`;
  } else {
    labels = [];
    help = 'Move the points on the figure, then Check.';
  }
  return { help, rows: labels.map(input) };
}
