/**
 * The app's top bar: the brand (back to the gallery), presenter view, the
 * dark theme, the reader's letter for the curve parameter, full screen and help.
 */
import { h } from './dom';
import { LETTERS, LETTER_FORMS, type Letter } from '../render/notation';
import type { Settings } from './settings';

/** What the top bar's controls do. */
export interface TopBarActions {
  projector(): void;
  dark(): void;
  letter(letter: Letter): void;
  fullscreen(): void;
  help(): void;
}

const LETTER_WORDS: Record<Letter, string> = { mu: 'lecture', u: 'slides', t: 'practical' };

function button(
  label: string,
  title: string,
  action: () => void,
  pressed?: boolean,
  className?: string,
): HTMLButtonElement {
  return h(
    'button',
    {
      type: 'button',
      class: className,
      title,
      'aria-pressed': pressed === undefined ? undefined : String(pressed),
      onclick: action,
    },
    label,
  );
}

export class TopBar {
  readonly element: HTMLElement;
  private readonly projectorButton: HTMLButtonElement;
  private readonly darkButton: HTMLButtonElement;
  private readonly letterSelect: HTMLSelectElement;

  constructor(settings: Readonly<Settings>, actions: TopBarActions) {
    this.projectorButton = button(
      'Presenter',
      'Presenter view: the figure fills the screen, large captions and strokes, high contrast (P)',
      () => actions.projector(),
      settings.projector,
      'for-projector',
    );
    this.darkButton = button('Dark', 'Dark theme (D)', () => actions.dark(), settings.dark);
    const select = h(
      'select',
      {
        class: 'letter-setting',
        'aria-label': 'Parameter letter',
        title: `How the curve parameter is written: ${LETTERS.map((l) => `${LETTER_FORMS[l].plain} as in ${LETTER_FORMS[l].source}`).join(', ')}`,
        onchange: () => actions.letter(select.value as Letter),
      },
      ...LETTERS.map((l) =>
        h('option', { value: l }, `${LETTER_FORMS[l].plain} (${LETTER_WORDS[l]})`),
      ),
    );
    select.value = settings.letter;
    this.letterSelect = select;
    this.element = h(
      'header',
      { class: 'top-bar' },
      h('a', { class: 'brand', href: '#/' }, 'Spline Lab'),
      h(
        'nav',
        { class: 'app-tools', 'aria-label': 'Display' },
        this.projectorButton,
        this.darkButton,
        select,
        button(
          'Full screen',
          'Full screen (F)',
          () => actions.fullscreen(),
          undefined,
          'for-projector',
        ),
        button('?', 'Help: touch, mouse, keyboard and clicker (?)', () => actions.help()),
      ),
    );
  }

  /** Presenter view and the dark theme are on or off. */
  pressed(projector: boolean, dark: boolean): void {
    this.projectorButton.setAttribute('aria-pressed', String(projector));
    this.darkButton.setAttribute('aria-pressed', String(dark));
  }

  /** The letter in force. */
  letter(letter: Letter): void {
    this.letterSelect.value = letter;
  }
}
