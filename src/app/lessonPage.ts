/**
 * Hosts one lesson: its figures, the construction controls, its side panel,
 * and the frame that keeps them in step. Work is done by kind of change:
 * a new state redraws the figures and updates the panel; a hover redraws the
 * figures only; a pan, zoom or resize redraws only its own figure; an idle
 * page does nothing.
 */
import { fitToWidth, refitAll } from '../render/fit';
import type { Theme } from '../render/theme';
import { ParameterControl, StepControl } from './controls';
import { memoize } from './derive';
import { h } from './dom';
import { download, figuresToPng, figuresToSvg } from './exportFigure';
import { FigureView } from './figureView';
import { type KeyTarget, bindingFor } from './keymap';
import { buildLayout } from './layout';
import type { AnyLesson, DrawInfo, LessonPanel } from './lesson';
import { LessonStore, type Loaded } from './lessonState';
import type { LessonMeta } from './meta';
import { UrlSync } from './urlSync';

/** What the app shell offers a lesson page. */
export interface Shell {
  theme(): Theme;
  notice(message: string): void;
  announce(message: string): void;
}

let firstDrawMarked = false;
let framesMeasured = 0;
/** The name of each frame's measure in the Performance timeline. */
const FRAME = 'spline-lab:frame';

export class LessonPage<S, M> implements KeyTarget {
  readonly element: HTMLElement;
  readonly store: LessonStore<S>;
  readonly figures: FigureView<S, M>[];
  readonly model: (state: S) => M;
  private readonly panel: LessonPanel<S, M>;
  private readonly url: UrlSync;
  private readonly parameter?: ParameterControl<S>;
  private readonly steps?: StepControl<S>;
  private readonly undoButton: HTMLButtonElement;
  private readonly redoButton: HTMLButtonElement;
  private hover: string | null = null;
  private frame = 0;
  // What the next frame must do.
  private drawnState: S | null = null;
  private panelState: S | null = null;
  private hoverChanged = false;
  private refreshAll = true;
  private readonly dirtyFigures = new Set<FigureView<S, M>>();
  private readonly unsubscribe: () => void;
  private readonly panelResize: ResizeObserver;
  private panelWidth = -1;
  private panelWidthChanged = false;
  /** The panel changed: fit its wide content at the start of the next frame. */
  private fitPending = false;

  constructor(
    readonly meta: LessonMeta,
    readonly lesson: AnyLesson,
    loaded: Loaded<S>,
    private readonly shell: Shell,
  ) {
    this.store = new LessonStore<S>(lesson, loaded.state);
    this.model = memoize((state: S) => lesson.derive(state) as M);
    const set = (next: S, options?: { coalesce?: string; windowMs?: number; record?: boolean }) =>
      this.store.set(next, options);
    this.figures = lesson.figures.map(
      (spec) =>
        new FigureView<S, M>(spec, {
          get: () => this.store.state,
          model: () => this.current(),
          set,
          theme: () => shell.theme(),
          info: () => this.info(),
          setHover: (id) => this.setHover(id),
          announce: (text) => shell.announce(text),
          invalidate: (figure) => this.invalidateFigure(figure),
          viewChanged: () => this.url.schedule(300),
          hold: () => this.url.hold(),
          settle: () => this.url.write(),
        }),
    );
    this.panel = lesson.panel({
      get: () => this.store.state,
      model: () => this.current(),
      set,
      notice: (message) => shell.notice(message),
      setHover: (id) => this.setHover(id),
      theme: () => shell.theme(),
    });
    this.url = new UrlSync(lesson.slug, () => this.store.query(this.views()));

    const host = { get: () => this.store.state, set, settle: () => this.url.write() };
    if (lesson.parameter) this.parameter = new ParameterControl<S>(lesson.parameter, host);
    if (lesson.steps) this.steps = new StepControl<S>(lesson.steps, host);
    this.undoButton = h(
      'button',
      { type: 'button', title: 'Undo (Ctrl+Z)', onclick: () => this.undo() },
      'Undo',
    );
    this.redoButton = h(
      'button',
      { type: 'button', title: 'Redo (Ctrl+Shift+Z)', onclick: () => this.redo() },
      'Redo',
    );

    const stage = h(
      'section',
      { class: 'stage', 'aria-label': 'Figure' },
      buildLayout(lesson.layout, new Map(this.figures.map((f) => [f.spec.id, f.element]))),
      h('div', { class: 'controls' }, this.parameter?.element, this.steps?.element),
    );
    const aside = h(
      'aside',
      { class: 'panel', 'aria-label': 'Explanation' },
      this.presetButtons(),
      this.panel.element,
    );
    this.element = h(
      'div',
      { class: 'lesson-page', 'data-lesson': lesson.slug },
      h('div', { class: 'lesson-head' }, h('h1', {}, meta.title), this.toolbar()),
      h('div', { class: 'lesson-body' }, stage, aside),
    );

    // Formulas fit the panel's width; its height follows its content, so only
    // a change of width may refit them (else fitting could feed itself).
    this.panelResize = new ResizeObserver(([entry]) => {
      const width = Math.round(entry.contentRect.width);
      if (width !== this.panelWidth) {
        this.panelWidth = width;
        this.panelWidthChanged = true;
        this.requestFrame();
      }
    });
    this.panelResize.observe(aside);
    for (const issue of loaded.issues) shell.notice(`Ignored from the link: ${issue}.`);
    this.applyViews(loaded.views);
    this.unsubscribe = this.store.subscribe(() => {
      this.requestFrame();
      this.url.schedule();
    });
    this.requestFrame();
    // The link of the state the page opened with is written at once: it is final.
    this.url.write();
  }

  private toolbar(): HTMLElement {
    const button = (label: string, title: string, action: () => void) =>
      h('button', { type: 'button', title, onclick: action }, label);
    return h(
      'div',
      { class: 'lesson-tools', role: 'toolbar', 'aria-label': 'Lesson tools' },
      this.undoButton,
      this.redoButton,
      button('Fit view', 'Fit the view to the figure (0)', () => this.fit()),
      button('Copy link', 'Copy a link to exactly this view', () => void this.copyLink()),
      button('PNG', 'Save the figure as a PNG image', () => void this.exportPng()),
      button('SVG', 'Save the figure as an SVG drawing', () => this.exportSvg()),
    );
  }

  private presetButtons(): HTMLElement | null {
    const presets = this.lesson.presets;
    if (!presets?.length) return null;
    return h(
      'div',
      { class: 'presets', role: 'group', 'aria-label': 'Presets' },
      h('span', { class: 'presets-title' }, 'Presets'),
      ...presets.map((preset) =>
        h(
          'button',
          {
            type: 'button',
            'data-preset': preset.id,
            onclick: () => {
              this.store.set(preset.apply(this.store.state));
              this.fit();
            },
          },
          preset.label,
        ),
      ),
    );
  }

  /** The model of the current state. */
  current(): M {
    return this.model(this.store.state);
  }

  info(): DrawInfo {
    return { hover: this.hover, thumbnail: false };
  }

  /** The views the user moved, by figure id, for the link. */
  private views(): Record<string, string> {
    const views: Record<string, string> = {};
    for (const figure of this.figures) {
      const text = figure.viewText();
      if (text !== null) views[figure.spec.id] = text;
    }
    return views;
  }

  private applyViews(views: Readonly<Record<string, string>>): void {
    for (const figure of this.figures) {
      const text = views[figure.spec.id] ?? null;
      if (!figure.applyView(text))
        this.shell.notice(
          `Ignored from the link: the view of “${figure.spec.title}” could not be read; it was fitted to the figure.`,
        );
    }
  }

  /** Redraws everything after a change of display settings (projector mode changes every size). */
  refresh(): void {
    refitAll(this.panel.element);
    this.refreshAll = true;
    this.requestFrame();
  }

  setHover(id: string | null): void {
    if (id === this.hover) return;
    this.hover = id;
    this.hoverChanged = true;
    this.requestFrame();
  }

  private invalidateFigure(figure: FigureView<S, M>): void {
    this.dirtyFigures.add(figure);
    this.requestFrame();
  }

  private requestFrame(): void {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.drawNow();
    });
  }

  /**
   * Does what the changes since the last frame need (also used before export).
   * Each frame's work is measured as `spline-lab:frame` (derive + draw +
   * panel), for the benchmark and the tests.
   */
  drawNow(): void {
    const start = performance.now();
    // Fit what the last frame changed first: its layout is clean now (the
    // browser laid it out to draw it), so reading widths forces no layout.
    if (this.fitPending) {
      this.fitPending = false;
      fitToWidth(this.panel.element);
    }
    const state = this.store.state;
    const model = this.model(state);
    const stateChanged = state !== this.drawnState || this.refreshAll;
    const all = stateChanged || this.hoverChanged;
    for (const figure of this.figures) {
      if (all || this.dirtyFigures.has(figure)) figure.draw(model);
    }
    this.dirtyFigures.clear();
    // On the first frame the figure goes first: the panel (a page of formulas
    // to typeset) follows in the next frame, so the figure shows sooner.
    const panelDue = (stateChanged || state !== this.panelState) && this.drawnState !== null;
    if (panelDue) {
      this.panelState = state;
      this.panel.update(model, state);
      this.parameter?.update(state);
      this.steps?.update(state);
      this.undoButton.disabled = !this.store.canUndo;
      this.redoButton.disabled = !this.store.canRedo;
    }
    if (this.hoverChanged) this.panel.hover?.(this.hover);
    if (panelDue || this.panelWidthChanged) {
      this.fitPending = true;
      this.requestFrame();
    }
    if (!panelDue && this.panelState !== state) this.requestFrame();
    this.drawnState = state;
    this.hoverChanged = false;
    this.refreshAll = false;
    this.panelWidthChanged = false;
    if (!firstDrawMarked) {
      firstDrawMarked = true;
      performance.mark('spline-lab:first-draw');
    }
    if (++framesMeasured % 1000 === 0) performance.clearMeasures(FRAME);
    performance.measure(FRAME, { start });
  }

  /** The shareable link of the current state. */
  link(): string {
    return this.url.link();
  }

  writeUrl(): void {
    this.url.write();
  }

  /** The address bar names this lesson without a state: it shows the current one again. */
  keepState(): void {
    this.url.adopt();
    this.url.write();
  }

  /** Applies a state typed into the address bar or reached by back/forward. */
  applyQuery(loaded: Loaded<S>): void {
    this.url.adopt();
    for (const issue of loaded.issues) this.shell.notice(`Ignored from the link: ${issue}.`);
    this.applyViews(loaded.views);
    const same = this.store.query() === new LessonStore<S>(this.lesson, loaded.state).query();
    if (same) {
      // Nothing changed, but the address bar must show the state in force.
      this.url.write();
      return;
    }
    this.store.set(loaded.state);
  }

  undo(): void {
    this.store.undo();
  }

  redo(): void {
    this.store.redo();
  }

  step(delta: number): void {
    if (this.steps) this.steps.step(delta);
    else this.parameter?.nudge(delta);
  }

  stepTo(end: 'first' | 'last'): void {
    this.steps?.stepTo(end);
  }

  togglePlay(): void {
    this.parameter?.toggle();
  }

  fit(): void {
    for (const figure of this.figures) figure.fit();
  }

  zoom(factor: number): void {
    this.figures.find((f) => f.movable)?.zoom(null, factor);
  }

  orbit(yaw: number, pitch: number): void {
    this.figures.find((f) => f.spec.kind === 'space')?.orbit(yaw, pitch);
  }

  async copyLink(): Promise<void> {
    this.url.write();
    const url = location.href;
    try {
      await navigator.clipboard.writeText(url);
      this.shell.notice('Link copied. It opens this lesson exactly as it is now.');
    } catch {
      this.shell.notice(`Copy this link: ${url}`);
    }
  }

  async exportPng(): Promise<void> {
    this.refreshAll = true;
    this.drawNow();
    const blob = await figuresToPng(this.figures, this.shell.theme().background);
    download(blob, `spline-lab-${this.lesson.slug}.png`);
  }

  exportSvg(): void {
    const svg = figuresToSvg(this.figures, this.current(), this.shell.theme(), this.info());
    download(new Blob([svg], { type: 'image/svg+xml' }), `spline-lab-${this.lesson.slug}.svg`);
  }

  /** Page-level keys (see keymap.ts); returns true when the key was used. */
  handleKey(e: KeyboardEvent): boolean {
    const binding = bindingFor(e);
    if (!binding) return false;
    binding.run(this);
    return true;
  }

  destroy(): void {
    // By now the address bar may already show another page: only remember
    // (and a write still pending sees the new address and leaves it alone).
    this.url.close();
    this.parameter?.stop();
    this.unsubscribe();
    this.panelResize.disconnect();
    cancelAnimationFrame(this.frame);
    for (const figure of this.figures) figure.destroy();
    this.panel.destroy?.();
  }
}
