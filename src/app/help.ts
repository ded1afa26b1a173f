import { h } from './dom';
import { keyHelp } from './keymap';

const KEYS: [string, string][] = [
  ['Tab / Shift+Tab', 'Focus the next / previous movable point or control'],
  ['Arrow keys (on a point)', 'Move the point; Shift: big steps, Alt: fine steps'],
  ['Ctrl+↑ / Ctrl+↓ (on a point in space)', 'Move the point along z'],
  ['Delete (on a point)', 'Remove the point, where the lesson allows it'],
  ['Double-click / long-press', 'Add a point on empty space, where the lesson allows it'],
  ['Drag empty space, wheel, pinch', 'Pan and zoom a figure; in space, drag to turn it'],
  ['Shift+drag (a point in space)', 'Move the point along one axis'],
  ['One finger (touch)', 'Scrolls the page; two fingers pan and zoom a figure'],
  ...keyHelp(),
];

export function helpDialog(): HTMLDialogElement {
  const dialog = h(
    'dialog',
    { class: 'help', 'aria-labelledby': 'help-title' },
    h('h2', { id: 'help-title' }, 'Keys and gestures'),
    h(
      'table',
      {},
      h(
        'tbody',
        {},
        ...KEYS.map(([key, what]) =>
          h('tr', {}, h('th', { scope: 'row' }, key), h('td', {}, what)),
        ),
      ),
    ),
    h('form', { method: 'dialog' }, h('button', { type: 'submit' }, 'Close')),
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
  dialog.showModal();
  dialog.scrollTop = 0;
  dialog.focus();
}
