/**
 * What the keys and the clicker do on a lesson page: each action is one of
 * the page's parts' own. The key table that calls them is keymap.ts.
 */
import { presenting } from './settings';
import type { PageKeys } from './keyTarget';
import type { LessonStore } from './lessonState';
import type { PageFigures } from './pageFigures';
import type { ParameterControl } from './parameterControl';
import type { Presenter } from './presenter';
import type { ScriptWalker } from './scriptWalker';

/** The parts of a lesson page the keys act on. */
export interface KeyedParts<S, M> {
  readonly store: LessonStore<S>;
  readonly walker: ScriptWalker<S>;
  readonly parameter?: ParameterControl<S>;
  readonly figures: PageFigures<S, M>;
  readonly presenter: Presenter;
  /** The step caption: Q poses its next step as a question. */
  readonly caption: { ask(): void };
  /** The page's element: its classes fold and show the side panel. */
  readonly element: HTMLElement;
  /** Draws and fits everything again (the side panel's width changed). */
  refresh(): void;
  lecturerControls(): void;
}

export function pageKeys<S, M>(page: KeyedParts<S, M>): PageKeys {
  const { store, walker, parameter, figures, presenter } = page;
  return {
    undo: () => store.undo(),
    redo: () => store.redo(),
    advance: (delta) => walker.advance(delta),
    stepTo: (end) => walker.stepTo(end),
    togglePlay: () => parameter?.toggle(),
    playSpeed: (delta) => parameter?.changeSpeed(delta),
    fit: () => figures.fit(),
    zoom: (factor) => figures.views.find((f) => f.movable)?.zoom(null, factor),
    orbit: (yaw, pitch) => figures.views.find((f) => f.spec.kind === 'space')?.orbit(yaw, pitch),
    sidePanel: () => {
      // Folded by default in presenter view, shown by default elsewhere.
      page.element.classList.toggle(presenting() ? 'panel-shown' : 'panel-folded');
      page.refresh();
    },
    lecturerControls: () => page.lecturerControls(),
    ask: () => page.caption.ask(),
    blank: () => presenter.blank(),
    unblank: () => presenter.unblank(),
    blanked: () => presenter.blanked,
    tool: (name) => presenter.toggle(name),
    clearInk: () => presenter.clearInk(),
  };
}
