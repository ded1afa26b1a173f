/**
 * Every key of the app, as one table: which keys, what they do, and who owns
 * them when a control has focus. The help dialog lists the same table, and the
 * tests walk it in every focus state.
 *
 * Ownership decides the clicker's reliability. A presentation clicker sends
 * PageDown/PageUp (some also B or `.` to blank the screen): those belong to
 * the page whatever has focus (a slider, a number field, a checkbox, a radio
 * group, a button, a point), and the focused control never also acts on them.
 * Keys a control uses itself (arrows and Home/End on a slider, Space on a
 * checkbox, arrows on a radio group, anything typed into a number field)
 * stay with that control and never also step.
 *
 * What the keys act on is keyTarget.ts; what has focus, keyFocus.ts.
 */
import { isControl, isTyping } from './keyFocus';
import type { KeyTarget } from './keyTarget';

// Still importable from here by the files that use them with the keymap.

/**
 * Who owns a key when something has focus:
 * - `page`: always the page's (clicker keys), even in a number field;
 * - `unlessTyping`: the page's, except while typing in a text or number field;
 * - `unlessControl`: the page's only when no control has focus (a control's
 *   own keys: arrows and Space on a slider, a checkbox, a radio group, a
 *   button or a point).
 */
export type Owner = 'page' | 'unlessTyping' | 'unlessControl';

export interface Binding {
  keys: readonly string[];
  /** With Ctrl (or ⌘ on a Mac). */
  mod?: boolean;
  shift?: boolean;
  owner: Owner;
  /** For the help: which keys, and what they do ('' for a key listed with another). */
  help: [string, string];
  /** Works on the gallery too (not only in a lesson). */
  app?: boolean;
  run(target: KeyTarget): void;
}

export const KEYS: readonly Binding[] = [
  {
    keys: ['PageDown'],
    owner: 'page',
    help: ['PageDown, →, space', 'Next step; after the last, the next scene (a clicker works)'],
    run: (t) => t.advance(1),
  },
  {
    keys: ['ArrowRight', 'ArrowDown', ' '],
    owner: 'unlessControl',
    help: ['', ''],
    run: (t) => t.advance(1),
  },
  {
    keys: ['PageUp'],
    owner: 'page',
    help: ['PageUp, ←', 'Previous step; before the first, the previous scene'],
    run: (t) => t.advance(-1),
  },
  {
    keys: ['ArrowLeft', 'ArrowUp'],
    owner: 'unlessControl',
    help: ['', ''],
    run: (t) => t.advance(-1),
  },
  {
    keys: ['Home'],
    owner: 'unlessTyping',
    help: ['Home / End', 'First / last step of this scene'],
    run: (t) => t.stepTo('first'),
  },
  { keys: ['End'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.stepTo('last') },
  {
    keys: ['b', 'B', '.'],
    owner: 'unlessTyping',
    help: ['B or .', 'Blank the screen (any clicker key brings it back)'],
    run: (t) => t.blank(),
  },
  {
    keys: ['z', 'Z'],
    mod: true,
    shift: false,
    owner: 'unlessTyping',
    help: ['Ctrl+Z', 'Undo an edit (steps are not edits)'],
    run: (t) => t.undo(),
  },
  {
    keys: ['z', 'Z'],
    mod: true,
    shift: true,
    owner: 'unlessTyping',
    help: ['Ctrl+Shift+Z, Ctrl+Y', 'Redo'],
    run: (t) => t.redo(),
  },
  { keys: ['y', 'Y'], mod: true, owner: 'unlessTyping', help: ['', ''], run: (t) => t.redo() },
  {
    keys: ['k', 'K'],
    owner: 'unlessTyping',
    help: ['K', 'Play / pause the parameter'],
    run: (t) => t.togglePlay(),
  },
  {
    keys: ['>'],
    owner: 'unlessTyping',
    help: ['< >', 'Play slower / faster'],
    run: (t) => t.playSpeed(1),
  },
  { keys: ['<'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.playSpeed(-1) },
  {
    keys: ['0'],
    owner: 'unlessTyping',
    help: ['0, +, −', 'Fit the view, zoom in, zoom out'],
    run: (t) => t.fit(),
  },
  { keys: ['+', '='], owner: 'unlessTyping', help: ['', ''], run: (t) => t.zoom(1.25) },
  { keys: ['-'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.zoom(0.8) },
  {
    keys: ['['],
    owner: 'unlessTyping',
    help: ['[ ] and { }', 'Turn a figure in space left / right, tilt it down / up'],
    run: (t) => t.orbit(-15, 0),
  },
  { keys: [']'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.orbit(15, 0) },
  { keys: ['{'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.orbit(0, -10) },
  { keys: ['}'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.orbit(0, 10) },
  {
    keys: ['p', 'P'],
    owner: 'unlessTyping',
    app: true,
    help: ['P', 'Presenter view: the figure fills the screen, large captions'],
    run: (t) => t.presenter(),
  },
  {
    keys: ['m', 'M'],
    owner: 'unlessTyping',
    help: ['M', "Presenter view: show or hide the lecturer's controls (tools, slider, steps)"],
    run: (t) => t.lecturerControls(),
  },
  {
    keys: ['s', 'S'],
    owner: 'unlessTyping',
    help: ['S', 'Show or fold the side panel'],
    run: (t) => t.sidePanel(),
  },
  {
    keys: ['l', 'L'],
    owner: 'unlessTyping',
    help: ['L', 'Laser pointer'],
    run: (t) => t.tool('laser'),
  },
  {
    keys: ['i', 'I'],
    owner: 'unlessTyping',
    help: ['I / E', 'Ink: draw over the figure / erase the ink'],
    run: (t) => t.tool('ink'),
  },
  { keys: ['e', 'E'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.clearInk() },
  {
    keys: ['c', 'C'],
    owner: 'unlessTyping',
    help: ['C, N, A', 'Hide / reveal the curve, the numbers, the labels (predict, then show)'],
    run: (t) => t.tool('hideCurve'),
  },
  { keys: ['n', 'N'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.tool('hideNumbers') },
  { keys: ['a', 'A'], owner: 'unlessTyping', help: ['', ''], run: (t) => t.tool('hideLabels') },
  {
    keys: ['q', 'Q'],
    owner: 'unlessTyping',
    help: ['Q', 'Ask the room: pose the next step as a question; the next press reveals it'],
    run: (t) => t.ask(),
  },
  {
    keys: ['o', 'O'],
    owner: 'unlessTyping',
    help: ['O', 'Keep the current figure as a faint ghost to compare with'],
    run: (t) => t.tool('ghost'),
  },
  {
    keys: ['r', 'R'],
    owner: 'unlessTyping',
    help: ['R', 'Trail: trace the moving point while the parameter plays'],
    run: (t) => t.tool('trail'),
  },
  {
    keys: ['d', 'D'],
    owner: 'unlessTyping',
    app: true,
    help: ['D', 'Dark theme'],
    run: (t) => t.dark(),
  },
  {
    keys: ['f', 'F'],
    owner: 'unlessTyping',
    app: true,
    help: ['F', 'Full screen'],
    run: (t) => t.fullscreen(),
  },
  {
    keys: ['g', 'G'],
    owner: 'unlessTyping',
    app: true,
    help: ['G', 'Back to the gallery of lessons'],
    run: (t) => t.gallery(),
  },
  { keys: ['?'], owner: 'unlessTyping', app: true, help: ['?', 'This help'], run: (t) => t.help() },
];

/** Keys that bring a blanked screen back (and do nothing else then). */
const CLICKER = new Set(['PageDown', 'PageUp', 'b', 'B', '.', 'Escape', 'ArrowRight', 'ArrowLeft']);

/**
 * The binding for a key press, or null when the key belongs to whatever has
 * focus. `lesson` says whether a lesson page is open (else only app keys).
 */
export function bindingFor(e: KeyboardEvent, lesson = true): Binding | null {
  const mod = e.ctrlKey || e.metaKey;
  for (const binding of KEYS) {
    if (!binding.keys.includes(e.key)) continue;
    if (Boolean(binding.mod) !== mod) continue;
    if (binding.shift !== undefined && binding.shift !== e.shiftKey) continue;
    if (!lesson && !binding.app) return null;
    if (!binding.mod && e.altKey) return null;
    if (binding.owner === 'unlessTyping' && isTyping(e.target)) return null;
    if (binding.owner === 'unlessControl' && isControl(e.target)) return null;
    return binding;
  }
  return null;
}

/**
 * While the screen is blanked, a clicker key (or Escape) only brings it back:
 * the audience sees nothing change behind the black.
 */
export const restoresBlank = (e: KeyboardEvent): boolean =>
  !e.ctrlKey && !e.metaKey && !e.altKey && CLICKER.has(e.key);

/** Rows for the help dialog: [keys, what they do]. */
export const keyHelp = (lesson = true): [string, string][] =>
  KEYS.filter((b) => lesson || b.app)
    .map((b) => b.help)
    .filter(([keys]) => keys !== '');
