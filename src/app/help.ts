import { h } from './dom';

const KEYS: [string, string][] = [
  ['Tab / Shift+Tab', 'Focus the next / previous movable point or control'],
  ['Arrow keys (on a point)', 'Move the point; Shift: big steps, Alt: fine steps'],
  ['Delete (on a point)', 'Remove the point, where the lesson allows it'],
  ['Double-click / long-press', 'Add a point on empty space, where the lesson allows it'],
  ['PageDown, →, space', 'Next step of the construction (a presentation clicker works)'],
  ['PageUp, ←', 'Previous step'],
  ['Home / End', 'First / last step'],
  ['K', 'Play / pause the parameter'],
  ['Ctrl+Z / Ctrl+Shift+Z', 'Undo / redo'],
  ['0, +, −', 'Fit the view, zoom in, zoom out (or wheel, pinch, drag empty space)'],
  ['P', 'Projector mode: thick strokes, large labels, high contrast'],
  ['D', 'Dark theme'],
  ['F', 'Full screen'],
  ['G', 'Back to the gallery of lessons'],
  ['?', 'This help'],
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
