import { h } from './dom';
import { keyHelp } from './keymap';

/** With a finger: first on a touch screen, where it is all there is. */
const TOUCH: [string, string][] = [
  ['Drag a point', 'Move it; it stays under your finger'],
  ['Tap a point', 'Choose it: a “Delete” button appears where the lesson lets a point go'],
  ['Press and hold empty space', 'Add a point, where the lesson allows it'],
  ['One finger on empty space', 'Scrolls the page'],
  ['Two fingers', 'Pan and zoom a figure; in space, turn it'],
  [
    'Back / Next under the figure',
    'Step through the construction; past the last step, the next scene',
  ],
  [
    'Practice (top of the text)',
    'Exercises the app checks: tap a guess, type a number, or move the points',
  ],
];

/** With a mouse or pen. */
const POINTER: [string, string][] = [
  ['Drag a point', 'Move it'],
  ['Double-click empty space', 'Add a point, where the lesson allows it'],
  ['Right-click a point', 'Remove it, where the lesson allows it'],
  ['Drag empty space, wheel', 'Pan and zoom a figure; in space, drag to turn it'],
  ['Shift+drag (a point in space)', 'Move the point along one axis'],
];

/** With the keyboard (and a presentation clicker, which sends keys). */
const KEYS: [string, string][] = [
  ['Tab / Shift+Tab', 'Focus the next / previous movable point or control'],
  ['Arrow keys (on a point)', 'Move the point; Shift: big steps, Alt: fine steps'],
  ['Ctrl+↑ / Ctrl+↓ (on a point in space)', 'Move the point along z'],
  ['Delete (on a point)', 'Remove the point, where the lesson allows it'],
  ...keyHelp(),
];

const coarse = () => window.matchMedia?.('(pointer: coarse)').matches ?? false;

/** One section of the help: a heading and its gestures or keys, as a list that reflows on a phone. */
function section(title: string, rows: readonly [string, string][]): HTMLElement {
  return h(
    'section',
    {},
    h('h3', {}, title),
    h(
      'dl',
      {},
      rows.map(([key, what]) => h('div', {}, h('dt', {}, key), h('dd', {}, what))),
    ),
  );
}

export function helpDialog(): HTMLDialogElement {
  const touch = section('With a finger', TOUCH);
  const pointer = section('With a mouse or pen', POINTER);
  const keys = section('With the keyboard or a clicker', KEYS);
  const body = h('div', { class: 'help-body' });
  const dialog = h(
    'dialog',
    { class: 'help', 'aria-labelledby': 'help-title' },
    h('h2', { id: 'help-title' }, 'Help'),
    body,
    h('form', { method: 'dialog' }, h('button', { type: 'submit' }, 'Close')),
  );
  // Each time it opens, the device's own way of working comes first.
  dialog.addEventListener('help-open', () =>
    body.replaceChildren(...(coarse() ? [touch, pointer, keys] : [keys, pointer, touch])),
  );
  dialog.setAttribute('tabindex', '-1');
  dialog.addEventListener('click', (e) => {
    if (e.target === dialog) dialog.close();
  });
  return dialog;
}

/**
 * Opens the help at its top: the dialog itself takes focus, not the Close
 * button at the bottom, which would scroll a tall dialog (projector mode, a
 * phone) to its end.
 */
export function openHelp(dialog: HTMLDialogElement): void {
  dialog.dispatchEvent(new Event('help-open'));
  dialog.showModal();
  dialog.scrollTop = 0;
  dialog.focus();
}
