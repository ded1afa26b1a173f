/**
 * What has focus, as the keymap asks it: a field that takes typed text keeps
 * letters and `.`; a control with keys of its own (a button, a point, a
 * slider, a checkbox, a radio button) keeps its arrows and Space as well.
 */

/** A field that takes typed text: letters and `.` are its own. */
export const isTyping = (target: EventTarget | null): boolean =>
  target instanceof HTMLElement &&
  (target.isContentEditable ||
    target.tagName === 'TEXTAREA' ||
    target.tagName === 'SELECT' ||
    (target instanceof HTMLInputElement &&
      !['range', 'checkbox', 'radio', 'button', 'submit', 'reset', 'color'].includes(target.type)));

/** A control with keys of its own: a button, a point, a slider, a checkbox, a radio button. */
export const isControl = (target: EventTarget | null): boolean =>
  target instanceof HTMLElement &&
  (isTyping(target) ||
    target.tagName === 'BUTTON' ||
    target.tagName === 'A' ||
    target.tagName === 'INPUT' ||
    target.classList.contains('handle-proxy') ||
    target.getAttribute('role') === 'slider' ||
    target.getAttribute('role') === 'radio');
