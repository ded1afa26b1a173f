/**
 * Hosts one lesson: its figures, the construction controls, its side panel,
 * and the frame that keeps them in step. Work is done by kind of change:
 * a new state redraws the figures and updates the panel; a hover redraws the
 * figures only; a pan, zoom or resize redraws only its own figure; an idle
 * page does nothing.
 */
import { parseHash } from './router';
import { fitToWidth, refitAll } from '../render/fit';
import { closeTypesetBudget, openTypesetBudget, typesetWaiting } from '../render/formula';
import type { LabelBox } from '../render/labels';
import { holdUnseenWhilePressed } from '../render/unseen';
import type { Theme } from '../render/theme';
import { ParameterControl } from './controls';
import { memoize } from './derive';
import { h, setDisabled, setHidden, setText } from './dom';
import { download, figuresToPng, figuresToSvg } from './exportFigure';
import { FigureView } from './figureView';
import type { PresenterTool } from './keymap';
import { buildLayout } from './layout';
import type { AnyLesson, DrawInfo, LessonPanel, Point } from './lesson';
import { LessonStore, type Loaded } from './lessonState';
import type { LessonMeta } from './meta';
import { Presenter } from './presenter';
import { ScriptWalker } from './scriptWalker';
import { Trails } from './trails';
import { UrlSync } from './urlSync';
import { PracticeHost } from './practiceHost';
import { withLetter, withPractice } from './urlState';
import { chosenLetter } from '../render/notation';

/** What the app shell offers a lesson page. */
export interface Shell {
  theme(): Theme;
  notice(message: string): void;
  announce(message: string): void;
  /** Switches presenter view on or off. */
  togglePresenter(): void;
}

let firstDrawMarked = false;
let framesMeasured = 0;
/** The name of each frame's measure in the Performance timeline. */
const FRAME = 'spline-lab:frame';
/**
 * Milliseconds of figure drawing after which the panel waits for the next
 * frame (once): the figure answers the hand first, the text follows.
 */
const PANEL_BUDGET_MS = 12;
/** Milliseconds of a frame in which new formulas are typeset; the rest wait for the next frame. */
const TYPESET_BUDGET_MS = 20;

export class LessonPage<S, M> {
  readonly element: HTMLElement;
  readonly store: LessonStore<S>;
  readonly figures: FigureView<S, M>[];
  readonly model: (state: S) => M;
  private readonly panel: LessonPanel<S, M>;
  private readonly url: UrlSync;
  private readonly parameter?: ParameterControl<S>;
  /** The clicker's walk through the script: steps, scenes, their buttons and status. */
  readonly walker: ScriptWalker<S>;
  /** The lesson's exercises (absent for a lesson without any). */
  private readonly practice?: PracticeHost<S>;
  /** The room is asked to predict the next step (presenter's Q). */
  private asking = false;
  /** The step the question was asked at: any other step answers it. */
  private askedAt = '';
  private readonly undoButton: HTMLButtonElement;
  private readonly redoButton: HTMLButtonElement;
  private hover: string | null = null;
  private frame = 0;
  /** Undoes holdUnseenWhilePressed (unseen.ts). */
  private readonly releaseUnseen: () => void;
  // What the next frame must do.
  private drawnState: S | null = null;
  private panelState: S | null = null;
  /**
   * The panel has not been updated yet: it is kept out of sight (and out of the
   * accessibility tree) so its first frame shows no control of another scene.
   */
  private panelPending = true;
  /** The panel's update was put off to this frame: it is not put off again. */
  private panelDeferred = false;
  private hoverChanged = false;
  private refreshAll = true;
  private readonly dirtyFigures = new Set<FigureView<S, M>>();
  private readonly unsubscribe: () => void;
  private readonly panelResize: ResizeObserver;
  private readonly aboveStage: ResizeObserver;

  private panelWidth = -1;
  private panelWidthChanged = false;
  /** The panel changed: fit its wide content at the start of the next frame. */
  private fitPending = false;
  readonly presenter: Presenter;
  /** The model kept as a faint ghost (presenter tool), or null. */
  private ghostModel: M | null = null;
  /** The trail of each figure's moving point (presenter tool). */
  private readonly trails = new Trails();
  /** The step the caption and ink were last shown for. */
  private shownStep = '';
  /** The figures' box, and which figures the scene shows now (ids joined; '' for all). */
  private figureBox!: HTMLElement;
  private figuresShownKey = '';

  constructor(
    readonly meta: LessonMeta,
    readonly lesson: AnyLesson,
    loaded: Loaded<S>,
    private readonly shell: Shell,
  ) {
    this.store = new LessonStore<S>(lesson, loaded.state, loaded.scene);
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
          shown: () => this.presenter.shown(),
          ghost: () => this.ghostModel,
          trail: (figure) => this.trails.of(figure),
          marks: (figure) => this.practice?.practice.marks(figure) ?? [],
          tap: (figure, at) => this.practice?.practice.tap(figure, at) ?? false,
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
    this.url = new UrlSync(lesson.slug, () => {
      // An exercise's link: its id and seed, then the figure as the student has it now.
      // The reader's letter for the parameter goes first, when it is not the usual t.
      return withLetter(
        chosenLetter(),
        withPractice(this.practice?.link() ?? null, this.store.query(this.views())),
      );
    });

    const host = { get: () => this.store.state, set, settle: () => this.url.write() };
    if (lesson.parameter) this.parameter = new ParameterControl<S>(lesson.parameter, host);
    this.walker = new ScriptWalker<S>(lesson, this.store, {
      fit: () => this.fit(),
      announce: (text) => shell.announce(text),
      pauseAtSceneEnd: () => !document.documentElement.classList.contains('projector'),
    });
    this.practice = PracticeHost.of<S>(
      {
        lesson,
        store: this.store,
        walker: this.walker,
        element: () => this.element,
        figureBox: () => this.figureBox,
        shownFigureIds: () => this.figures.filter((f) => !f.element.hidden).map((f) => f.spec.id),
        fit: () => this.fit(),
        redraw: () => {
          this.refreshAll = true;
          this.requestFrame();
        },
        linkChanged: () => this.url.schedule(0),
      },
      loaded,
    );
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

    const figures = h(
      'div',
      { class: 'stage-figures' },
      buildLayout(lesson.layout, new Map(this.figures.map((f) => [f.spec.id, f.element]))),
    );
    this.figureBox = figures;
    this.presenter = new Presenter(
      figures,
      (tool) => this.toolChanged(tool),
      () => shell.togglePresenter(),
    );
    const stage = h(
      'section',
      { class: 'stage', 'aria-label': 'Figure' },
      this.controlsToggle,
      this.presenter.caption,
      figures,
      h(
        'div',
        { class: 'controls' },
        this.parameter?.element,
        this.walker.steps?.element,
        this.textToggle,
        this.presenter.toolbar,
      ),
    );
    const aside = h(
      'aside',
      { class: 'panel', 'aria-label': 'Explanation' },
      this.practice?.entry,
      this.practice?.practice.element,
      this.walker.sceneGroup,
      this.panel.element,
    );
    this.element = h(
      'div',
      { class: 'lesson-page', 'data-lesson': lesson.slug },
      h('div', { class: 'lesson-head' }, h('h1', {}, meta.title), this.toolbar()),
      h('div', { class: 'lesson-body' }, stage, aside),
    );
    // A control clicked with the pointer gives its focus back: the clicker's
    // arrows and Space then step the construction instead of ticking it again.
    this.element.addEventListener('click', (e) => {
      const target = document.activeElement;
      if (
        e.detail > 0 &&
        target instanceof HTMLElement &&
        this.element.contains(target) &&
        (target.tagName === 'BUTTON' ||
          (target instanceof HTMLInputElement && ['checkbox', 'radio'].includes(target.type)))
      )
        target.blur();
    });

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
    // On a phone the stage fills the first screen under whatever stands above it.
    this.aboveStage = new ResizeObserver(() => {
      const top = Math.round(stage.getBoundingClientRect().top + window.scrollY);
      if (top > 0) this.element.style.setProperty('--stage-top', `${top}px`);
    });
    for (const el of [document.querySelector('.top-bar'), document.querySelector('.notices')])
      if (el) this.aboveStage.observe(el);
    this.aboveStage.observe(this.element.querySelector('.lesson-head') as Element);

    this.panel.element.classList.add('panel-pending');
    // Formula fonts arriving late change widths measured before them: fit again.
    document.fonts?.addEventListener('loadingdone', this.fontsLoaded);
    this.releaseUnseen = holdUnseenWhilePressed(window, () => {
      this.fitPending = true;
      this.requestFrame();
    });
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
    // On a phone the tools past Undo and Redo fold under one button, so the
    // lesson's name and the figure keep the first screen.
    const more = h(
      'div',
      { class: 'tools-more', id: `tools-${this.lesson.slug}` },
      button('Fit view', 'Fit the view to the figure (0)', () => this.fit()),
      button('Copy link', 'Copy a link to exactly this view', () => void this.copyLink()),
      button('PNG', 'Save the figure as a PNG image', () => void this.exportPng()),
      button('SVG', 'Save the figure as an SVG drawing', () => this.exportSvg()),
      button('Handout', 'Print this lesson as a handout: its steps as vector pages, or a PDF', () =>
        this.openHandout(),
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
    return h(
      'div',
      { class: 'lesson-tools', role: 'toolbar', 'aria-label': 'Lesson tools' },
      this.undoButton,
      this.redoButton,
      toggle,
      more,
    );
  }

  private readonly fontsLoaded = (): void => {
    refitAll(this.panel.element);
    refitAll(this.presenter.caption);
    this.fitPending = true;
    this.requestFrame();
  };

  advance(delta: 1 | -1): void {
    this.walker.advance(delta);
  }

  /**
   * Predict, then show: the caption asks the room what the next step will
   * show (nothing of it is drawn yet); the next press reveals it. Pressed
   * again, the question is withdrawn.
   */
  ask(): void {
    const { k, count } = this.walker.stepOf(this.store.state);
    if (!this.asking && k >= count) {
      this.shell.announce('The last step of this scene: nothing further to predict');
      return;
    }
    this.asking = !this.asking;
    this.askedAt = `${this.store.scene}/${k}`;
    this.presenter.asking(this.asking);
    this.shownStep = '';
    this.panelState = null;
    this.requestFrame();
  }

  stepTo(end: 'first' | 'last'): void {
    this.walker.stepTo(end);
  }

  /** A presenter tool was switched: redraw what it changes. */
  private toolChanged(tool: PresenterTool | 'blank'): void {
    if (tool === 'ghost') this.ghostModel = this.presenter.tools.ghost ? this.current() : null;
    if (tool === 'trail') this.trails.clear();
    if (tool !== 'blank' && tool !== 'laser' && tool !== 'ink') {
      this.refreshAll = true;
      this.requestFrame();
    }
  }

  get blanked(): boolean {
    return this.presenter.blanked;
  }

  /** The caption of the current step, for presenter view; ink is cleared when the step changes. */
  private updateCaption(state: S, model: M): void {
    const steps = this.lesson.steps;
    const scenes = this.lesson.scenes ?? [];
    const { k, count } = this.walker.stepOf(state);
    const key = `${this.store.scene}/${k}`;
    if (key !== this.shownStep) {
      if (this.shownStep !== '') this.presenter.clearInk();
      this.shownStep = key;
    }
    if (!document.documentElement.classList.contains('projector')) return;
    const scene = scenes[this.store.scene];
    const sceneAt = (k: number) =>
      scene
        ? `${scene.label} · ${scenes.length > 1 ? `scene ${this.store.scene + 1}/${scenes.length}, ` : ''}step ${k}/${count}`
        : '';
    const sceneText = sceneAt(k);
    // One caption height for the whole scene: the figure keeps its size as the clicker steps.
    if (steps)
      this.presenter.reserveFor(
        `${this.store.scene}/${count}/${window.innerWidth}/${this.element.classList.contains('panel-shown')}`,
        count,
        (j) => {
          const at = { ...this.store.state, [steps.key]: j } as S;
          return {
            scene: sceneAt(j),
            step: steps.describe(at, j),
            formula: steps.formula?.(this.model(at), at) ?? null,
          };
        },
      );
    if (this.asking && key !== this.askedAt) {
      this.asking = false;
      this.presenter.asking(false);
    }
    if (this.asking) {
      this.presenter.setCaption(
        sceneText,
        `Predict before the next press: what will step ${k + 1} show, and why?`,
        null,
      );
      return;
    }
    this.presenter.setCaption(
      sceneText,
      steps ? steps.describe(state, k) : '',
      steps?.formula?.(model, state) ?? null,
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

  /** Redraws everything after a change of display settings (presenter view changes every size). */
  refresh(): void {
    refitAll(this.panel.element);
    this.refreshAll = true;
    this.panelState = null;
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
      fitToWidth(this.presenter.caption);
    }
    const typesetting = performance.now();
    // Formulas that waited for this frame, then this frame's own (see formula.ts).
    if (openTypesetBudget(TYPESET_BUDGET_MS) > 0) {
      this.fitPending = true;
      this.requestFrame();
    }
    const state = this.store.state;
    const deriving = performance.now();
    const model = this.model(state);
    const drawing = performance.now();
    const stateChanged = state !== this.drawnState || this.refreshAll;
    if (state !== this.drawnState && this.presenter.tools.trail)
      this.trails.extend(this.figures, model);
    if (stateChanged) this.showFigures(state);
    const all = stateChanged || this.hoverChanged;
    for (const figure of this.figures) {
      if (figure.element.hidden) continue;
      if (!all && !this.dirtyFigures.has(figure)) continue;
      const from = performance.now();
      figure.draw(model, this.refreshAll);
      performance.measure(`${FRAME}:figure:${figure.spec.id}`, { start: from });
    }
    this.dirtyFigures.clear();
    const panelStart = performance.now();
    // On the first frame the figure goes first: the panel (a page of formulas
    // to typeset) follows in the next frame, so the figure shows sooner. So it
    // does when the figures took long (a new scene): one long task would hold
    // the pointer and keys up, two shorter ones do not.
    const wanted = (stateChanged || state !== this.panelState) && this.drawnState !== null;
    const deferred = wanted && !this.panelDeferred && performance.now() - start > PANEL_BUDGET_MS;
    this.panelDeferred = deferred;
    const panelDue = wanted && !deferred;
    if (panelDue) {
      this.panelState = state;
      this.panel.update(model, state);
      if (this.panelPending) {
        this.panelPending = false;
        this.panel.element.classList.remove('panel-pending');
      }
      this.updateCaption(state, model);
      this.parameter?.update(state);
      this.walker.update(state);
      setDisabled(this.undoButton, !this.store.canUndo);
      setDisabled(this.redoButton, !this.store.canRedo);
    }
    if (this.hoverChanged) this.panel.hover?.(this.hover);
    if (panelDue || this.panelWidthChanged) {
      this.fitPending = true;
      this.requestFrame();
    }
    if (!panelDue && this.panelState !== state) this.requestFrame();
    if (typesetWaiting()) {
      this.fitPending = true;
      this.requestFrame();
    }
    closeTypesetBudget();
    this.drawnState = state;
    this.hoverChanged = false;
    this.refreshAll = false;
    this.panelWidthChanged = false;
    if (!firstDrawMarked) {
      firstDrawMarked = true;
      performance.mark('spline-lab:first-draw');
    }
    // The frame ends here: the measuring below is the tests' and the
    // benchmark's, not the app's (a fresh machine once saw 56 ms go inside these
    // calls, its parts summing to 7 ms).
    const end = performance.now();
    if (++framesMeasured % 1000 === 0) performance.clearMeasures();
    // The frame, and its parts: fitting, waiting formulas, the model, the figures, the panel.
    performance.measure(`${FRAME}:fit`, { start, end: typesetting });
    performance.measure(`${FRAME}:typeset`, { start: typesetting, end: deriving });
    performance.measure(`${FRAME}:derive`, { start: deriving, end: drawing });
    performance.measure(`${FRAME}:figures`, { start: drawing, end: panelStart });
    performance.measure(`${FRAME}:panel`, { start: panelStart, end });
    performance.measure(FRAME, { start, end });
  }

  /** The figures on screen: what an export saves. */
  private shownFigures(): FigureView<S, M>[] {
    return this.figures.filter((figure) => !figure.element.hidden);
  }

  /**
   * Shows the figures this state's scene declares and hides the others, with
   * any row, column or grid of the layout left with no figure to show.
   */
  private showFigures(state: S): void {
    const ids = this.lesson.figuresShown?.(state) ?? null;
    const key = ids === null ? '' : ids.join(',');
    if (key === this.figuresShownKey) return;
    this.figuresShownKey = key;
    for (const figure of this.figures)
      setHidden(figure.element, ids !== null && !ids.includes(figure.spec.id));
    const boxes = [...this.figureBox.querySelectorAll<HTMLElement>('.figures')].reverse();
    for (const box of boxes)
      setHidden(
        box,
        ![...box.children].some(
          (child) =>
            child instanceof HTMLElement &&
            !child.hidden &&
            !child.matches('.grid-heading, .grid-corner'),
        ),
      );
  }

  /**
   * Resolves when the page is settled: the state is final, its frame drawn, the
   * panel updated and the link written. Tests wait on this instead of sleeping.
   */
  async settled(): Promise<void> {
    const frame = () => new Promise<void>((resolve) => requestAnimationFrame(() => resolve()));
    await frame();
    for (let i = 0; i < 600; i++) {
      const drawing =
        this.frame !== 0 ||
        this.fitPending ||
        typesetWaiting() ||
        // Formula fonts still on their way: the caption and the figure beside it change size when they come.
        document.fonts?.status === 'loading' ||
        // The room a scene holds for its longest step, measured once the status is laid out.
        this.walker.steps?.measuring === true ||
        this.panelState !== this.store.state ||
        this.drawnState !== this.store.state;
      // The state is final: the link it would write in a moment is written now
      // (a test waiting out the debounce waited 100 ms for nothing).
      if (!drawing && this.url.pending) this.url.write();
      if (!drawing) return;
      await frame();
    }
  }

  /**
   * Where a figure's point is on the screen (client pixels), and where its
   * handle `id` is in the figure's coordinates: for tests that drag a point
   * to a place worked out by hand.
   */
  probe(figure: string, point: readonly number[] | null, id: string | null) {
    const view = this.figures.find((f) => f.spec.id === figure);
    if (!view) return null;
    const box = view.canvas.getBoundingClientRect();
    const screen = point ? view.view.toScreen(point as Point) : null;
    const handle = id ? view.handlePosition(id) : null;
    return {
      screen: screen ? [box.left + screen[0], box.top + screen[1]] : null,
      handle,
    };
  }

  /** Each figure's labels as last drawn, with its size: for the overlap check. */
  labelBoxes(): {
    figure: string;
    width: number;
    height: number;
    labels: readonly LabelBox[];
    crossed: string[];
  }[] {
    return this.figures.map((f) => ({
      figure: f.spec.id,
      width: f.view.width,
      height: f.view.height,
      labels: f.labels,
      crossed: f.crossedLabels(),
    }));
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
    if (this.practice?.applyLink(loaded)) return;
    this.walker.restart(loaded.scene);
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

  togglePlay(): void {
    this.parameter?.toggle();
  }

  playSpeed(delta: 1 | -1): void {
    this.parameter?.changeSpeed(delta);
  }

  /**
   * Presenter view projects the figure, the caption and the formula; the
   * lecturer's toolbar, slider, steps and tools stay off the room's screen
   * until asked for (M, or the small corner button).
   */
  private readonly controlsToggle = h(
    'button',
    {
      type: 'button',
      class: 'controls-toggle',
      'aria-label': "Lecturer's controls",
      'aria-expanded': 'false',
      title: "Show the lecturer's controls (M)",
      onclick: () => this.lecturerControls(),
    },
    '☰',
  );

  /**
   * A phone: the lesson's text (the step's numbers, its table) opens under
   * the figure in one tap, with the figure kept in sight above it; a second
   * tap goes back to the figure alone.
   */
  private readonly textToggle = h(
    'button',
    {
      type: 'button',
      class: 'text-toggle',
      'aria-expanded': 'false',
      onclick: () => this.toggleText(),
    },
    'Text and numbers ▾',
  );

  private toggleText(): void {
    const open = this.element.classList.toggle('reading');
    this.textToggle.setAttribute('aria-expanded', String(open));
    setText(this.textToggle, open ? 'Figure only ▴' : 'Text and numbers ▾');
    const aside = this.element.querySelector('.panel');
    requestAnimationFrame(() => {
      if (!open || !aside) window.scrollTo({ top: 0 });
      else {
        const stage = this.figureBox.closest('.stage')!.getBoundingClientRect().height;
        window.scrollTo({ top: aside.getBoundingClientRect().top + window.scrollY - stage });
      }
    });
  }

  lecturerControls(): void {
    const shown = this.element.classList.toggle('controls-shown');
    this.controlsToggle.setAttribute('aria-expanded', String(shown));
    this.controlsToggle.title = shown
      ? "Hide the lecturer's controls (M)"
      : "Show the lecturer's controls (M)";
    this.refresh();
  }

  /** Shows or folds the side panel (folded by default in presenter view). */
  sidePanel(): void {
    const presenting = document.documentElement.classList.contains('projector');
    this.element.classList.toggle(presenting ? 'panel-shown' : 'panel-folded');
    this.refresh();
  }

  tool(name: PresenterTool): void {
    this.presenter.toggle(name);
  }

  blank(): void {
    this.presenter.blank();
  }

  unblank(): void {
    this.presenter.unblank();
  }

  clearInk(): void {
    this.presenter.clearInk();
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

  /** The handout of the lesson as it is now (its link carries the state and the views). */
  openHandout(): void {
    this.url.write();
    const { slug, query } = parseHash(this.url.link());
    location.hash = `#/${slug}/handout${query ? `?${query}` : ''}`;
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
    const blob = await figuresToPng(this.shownFigures(), this.shell.theme());
    download(blob, `spline-lab-${this.lesson.slug}.png`);
  }

  exportSvg(): void {
    const svg = figuresToSvg(this.shownFigures(), this.current(), this.shell.theme(), this.info());
    download(new Blob([svg], { type: 'image/svg+xml' }), `spline-lab-${this.lesson.slug}.svg`);
  }

  destroy(): void {
    this.practice?.stopWalk();
    // By now the address bar may already show another page: only remember
    // (and a write still pending sees the new address and leaves it alone).
    this.url.close();
    this.parameter?.stop();
    this.unsubscribe();
    this.panelResize.disconnect();
    this.aboveStage.disconnect();
    document.fonts?.removeEventListener('loadingdone', this.fontsLoaded);
    this.releaseUnseen();
    cancelAnimationFrame(this.frame);
    for (const figure of this.figures) figure.destroy();
    this.presenter.destroy();
    this.panel.destroy?.();
  }
}
