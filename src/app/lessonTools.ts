/**
 * A lesson page's own buttons: the toolbar by its title (Undo, Redo and the
 * tools folded under More on a phone), the lecturer's corner button in
 * presenter view, and a phone's "Text and numbers" under the figure.
 */
import { h, setDisabled, setText } from './dom';

/** What the buttons do: the page's actions. */
export interface ToolActions {
  undo(): void;
  redo(): void;
  fit(): void;
  copyLink(): void;
  exportPng(): void;
  exportSvg(): void;
  openHandout(): void;
  lecturerControls(): void;
}

export class LessonTools {
  /** The toolbar beside the lesson's title. */
  readonly toolbar: HTMLElement;
  /**
   * Presenter view projects the figure, the caption and the formula; the
   * lecturer's toolbar, slider, steps and tools stay off the room's screen
   * until asked for (M, or this small corner button).
   */
  readonly controlsToggle: HTMLButtonElement;
  /**
   * A phone: the lesson's text (the step's numbers, its table) opens under
   * the figure in one tap, with the figure kept in sight above it; a second
   * tap goes back to the figure alone.
   */
  readonly textToggle: HTMLButtonElement;
  private readonly undoButton: HTMLButtonElement;
  private readonly redoButton: HTMLButtonElement;

  constructor(
    slug: string,
    actions: ToolActions,
    private readonly page: () => { element: HTMLElement; figureBox: HTMLElement },
  ) {
    const button = (label: string, title: string, action: () => void) =>
      h('button', { type: 'button', title, onclick: action }, label);
    this.undoButton = button('Undo', 'Undo (Ctrl+Z)', () => actions.undo());
    this.redoButton = button('Redo', 'Redo (Ctrl+Shift+Z)', () => actions.redo());
    // On a phone the tools past Undo and Redo fold under one button, so the
    // lesson's name and the figure keep the first screen.
    const more = h(
      'div',
      { class: 'tools-more', id: `tools-${slug}` },
      button('Fit view', 'Fit the view to the figure (0)', () => actions.fit()),
      button('Copy link', 'Copy a link to exactly this view', () => actions.copyLink()),
      button('PNG', 'Save the figure as a PNG image', () => actions.exportPng()),
      button('SVG', 'Save the figure as an SVG drawing', () => actions.exportSvg()),
      button('Handout', 'Print this lesson as a handout: its steps as vector pages, or a PDF', () =>
        actions.openHandout(),
      ),
    );
    const toggle = h(
      'button',
      {
        type: 'button',
        class: 'tools-toggle',
        'aria-expanded': 'false',
        'aria-controls': more.id,
        title: 'More tools: fit, link, PNG, SVG, handout',
        onclick: () => {
          const open = more.classList.toggle('open');
          toggle.setAttribute('aria-expanded', String(open));
        },
      },
      'More',
    );
    this.toolbar = h(
      'div',
      { class: 'lesson-tools', role: 'toolbar', 'aria-label': 'Lesson tools' },
      this.undoButton,
      this.redoButton,
      toggle,
      more,
    );
    this.controlsToggle = h(
      'button',
      {
        type: 'button',
        class: 'controls-toggle',
        'aria-label': "Lecturer's controls",
        'aria-expanded': 'false',
        title: "Show the lecturer's controls (M)",
        onclick: () => actions.lecturerControls(),
      },
      '☰',
    );
    this.textToggle = h(
      'button',
      {
        type: 'button',
        class: 'text-toggle',
        'aria-expanded': 'false',
        onclick: () => this.toggleText(),
      },
      'Text and numbers ▾',
    );
  }

  /** Undo and Redo are offered when there is something to undo or redo. */
  history(canUndo: boolean, canRedo: boolean): void {
    setDisabled(this.undoButton, !canUndo);
    setDisabled(this.redoButton, !canRedo);
  }

  /** The lecturer's controls were shown or hidden: the corner button says which. */
  controlsShown(shown: boolean): void {
    this.controlsToggle.setAttribute('aria-expanded', String(shown));
    this.controlsToggle.title = shown
      ? "Hide the lecturer's controls (M)"
      : "Show the lecturer's controls (M)";
  }

  private toggleText(): void {
    const { element, figureBox } = this.page();
    const open = element.classList.toggle('reading');
    this.textToggle.setAttribute('aria-expanded', String(open));
    setText(this.textToggle, open ? 'Figure only ▴' : 'Text and numbers ▾');
    const aside = element.querySelector('.panel');
    requestAnimationFrame(() => {
      if (!open || !aside) window.scrollTo({ top: 0 });
      else {
        const stage = figureBox.closest('.stage')!.getBoundingClientRect().height;
        window.scrollTo({ top: aside.getBoundingClientRect().top + window.scrollY - stage });
      }
    });
  }
}
