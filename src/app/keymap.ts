/**
 * The lesson page's keys, as one table: which keys, what they do, and when a
 * focused control keeps them for itself. The help dialog lists the same table.
 */

/** What the keys act on: the lesson page. */
export interface KeyTarget {
  undo(): void;
  redo(): void;
  step(delta: number): void;
  stepTo(end: 'first' | 'last'): void;
  togglePlay(): void;
  fit(): void;
  zoom(factor: number): void;
  /** Turns the first figure in space, in degrees. */
  orbit(yaw: number, pitch: number): void;
}

export interface Binding {
  keys: readonly string[];
  /** With Ctrl (or ⌘ on a Mac). */
  mod?: boolean;
  shift?: boolean;
  /** For the help: which keys, and what they do. */
  help: [string, string];
  /**
   * Keys a focused button or point uses itself (arrows, space): the binding
   * leaves them to it. A clicker's PageDown/PageUp always reach the page.
   */
  yieldsTo?: 'controls';
  run(target: KeyTarget): void;
}

export const LESSON_KEYS: readonly Binding[] = [
  {
    keys: ['z', 'Z'],
    mod: true,
    shift: false,
    help: ['Ctrl+Z', 'Undo'],
    run: (t) => t.undo(),
  },
  {
    keys: ['z', 'Z'],
    mod: true,
    shift: true,
    help: ['Ctrl+Shift+Z, Ctrl+Y', 'Redo'],
    run: (t) => t.redo(),
  },
  { keys: ['y', 'Y'], mod: true, help: ['', ''], run: (t) => t.redo() },
  {
    keys: ['PageDown'],
    help: ['PageDown, →, space', 'Next step of the construction (a presentation clicker works)'],
    run: (t) => t.step(1),
  },
  {
    keys: ['ArrowRight', 'ArrowDown', ' '],
    help: ['', ''],
    yieldsTo: 'controls',
    run: (t) => t.step(1),
  },
  { keys: ['PageUp'], help: ['PageUp, ←', 'Previous step'], run: (t) => t.step(-1) },
  { keys: ['ArrowLeft', 'ArrowUp'], help: ['', ''], yieldsTo: 'controls', run: (t) => t.step(-1) },
  { keys: ['Home'], help: ['Home / End', 'First / last step'], run: (t) => t.stepTo('first') },
  { keys: ['End'], help: ['', ''], run: (t) => t.stepTo('last') },
  { keys: ['k', 'K'], help: ['K', 'Play / pause the parameter'], run: (t) => t.togglePlay() },
  { keys: ['0'], help: ['0, +, −', 'Fit the view, zoom in, zoom out'], run: (t) => t.fit() },
  { keys: ['+', '='], help: ['', ''], run: (t) => t.zoom(1.25) },
  { keys: ['-'], help: ['', ''], run: (t) => t.zoom(0.8) },
  {
    keys: ['['],
    help: ['[ ] and { }', 'Turn a figure in space left / right, tilt it down / up'],
    run: (t) => t.orbit(-15, 0),
  },
  { keys: [']'], help: ['', ''], run: (t) => t.orbit(15, 0) },
  { keys: ['{'], help: ['', ''], run: (t) => t.orbit(0, -10) },
  { keys: ['}'], help: ['', ''], run: (t) => t.orbit(0, 10) },
];

const isTyping = (target: EventTarget | null) =>
  target instanceof HTMLElement &&
  (target.isContentEditable ||
    target.tagName === 'INPUT' ||
    target.tagName === 'TEXTAREA' ||
    target.tagName === 'SELECT');

const onControl = (target: EventTarget | null) =>
  target instanceof HTMLElement &&
  (target.tagName === 'BUTTON' || target.classList.contains('handle-proxy'));

/** The binding for a key press, or null when the key belongs to whatever has focus. */
export function bindingFor(e: KeyboardEvent): Binding | null {
  const mod = e.ctrlKey || e.metaKey;
  const clicker = e.key === 'PageDown' || e.key === 'PageUp';
  const onSlider = e.target instanceof HTMLInputElement && e.target.type === 'range';
  for (const binding of LESSON_KEYS) {
    if (!binding.keys.includes(e.key)) continue;
    if (Boolean(binding.mod) !== mod) continue;
    if (binding.shift !== undefined && binding.shift !== e.shiftKey) continue;
    if (!binding.mod) {
      if (e.altKey) return null;
      if (isTyping(e.target) && !(clicker && onSlider)) return null;
      if (binding.yieldsTo === 'controls' && onControl(e.target)) return null;
    }
    return binding;
  }
  return null;
}

/** Rows for the help dialog: [keys, what they do]. */
export const lessonKeyHelp = (): [string, string][] =>
  LESSON_KEYS.map((b) => b.help).filter(([keys]) => keys !== '');
