/**
 * Hosts one lesson: its figures, the construction controls, its side panel
 * and caption, wired to one store of its state. The frame that keeps them in
 * step is `pageFrame.ts`; the caption is `stepCaption.ts`; the page's own
 * buttons are `lessonTools.ts`.
 */
import { refitAll } from '../render/fit';
import { holdUnseenWhilePressed } from '../render/unseen';
import type { Theme } from '../render/theme';
import { ParameterControl } from './parameterControl';
import { memoize } from './derive';
import { h } from './dom';
import { download, figuresToPng, figuresToSvg } from './exportFigure';
import { FigureView } from './figureView';
import type { PageKeys, PresenterTool } from './keyTarget';
import { FigureArrangement } from './figureArrangement';
import { buildPageDom } from './pageDom';
import type { AnyLesson, DrawInfo, LessonPanel } from './lesson';
import { LessonStore, type Loaded } from './lessonState';
import { LessonTools } from './lessonTools';
import { PageLinks } from './pageLinks';
import type { LessonMeta } from './meta';
import { PageFrame } from './pageFrame';
import { labelBoxesOf, probeFigure } from './pageProbes';
import { Presenter } from './presenter';
import { ScriptWalker } from './scriptWalker';
import { StepCaption } from './stepCaption';
import { Trails } from './trails';
import type { UrlSync } from './urlSync';
import { PracticeHost } from './practiceHost';

/** What the app shell offers a lesson page. */
export interface Shell {
  theme(): Theme;
  notice(message: string): void;
  announce(message: string): void;
  /** Switches presenter view on or off. */
  togglePresenter(): void;
}

export class LessonPage<S, M> {
  readonly element: HTMLElement;
  readonly store: LessonStore<S>;
  readonly figures: FigureView<S, M>[];
  readonly model: (state: S) => M;
  private readonly panel: LessonPanel<S, M>;
  /** The page's links: the address bar, a link applied, Copy link and the handout. */
  readonly links: PageLinks<S, M>;
  private readonly url: UrlSync;
  private readonly parameter?: ParameterControl<S>;
  /** The clicker's walk through the script: steps, scenes, their buttons and status. */
  readonly walker: ScriptWalker<S>;
  /** The lesson's exercises (absent for a lesson without any). */
  private readonly practice?: PracticeHost<S>;
  private readonly tools: LessonTools;
  private readonly frame: PageFrame<S, M>;
  private readonly caption: StepCaption<S, M>;
  private hover: string | null = null;
  /** Undoes holdUnseenWhilePressed (unseen.ts). */
  private readonly releaseUnseen: () => void;
  /**
   * The panel has not been updated yet: it is kept out of sight (and out of the
   * accessibility tree) so its first frame shows no control of another scene.
   */
  private panelPending = true;
  private readonly unsubscribe: () => void;
  /** Stops watching the page's layout (pageDom.ts). */
  private readonly stopLayout: () => void;
  readonly presenter: Presenter;
  /** The model kept as a faint ghost (presenter tool), or null. */
  private ghostModel: M | null = null;
  /** The trail of each figure's moving point (presenter tool). */
  private readonly trails = new Trails();
  /** The figures' box, and the figures in it as the scene shows and arranges them. */
  private readonly figureBox: HTMLElement;
  private readonly arrangement: FigureArrangement<S, M>;

  /** What the keys and the clicker do on this page (keymap.ts). */
  readonly keys: PageKeys = {
    undo: () => this.store.undo(),
    redo: () => this.store.redo(),
    advance: (delta) => this.walker.advance(delta),
    stepTo: (end) => this.walker.stepTo(end),
    togglePlay: () => this.parameter?.toggle(),
    playSpeed: (delta) => this.parameter?.changeSpeed(delta),
    fit: () => this.fit(),
    zoom: (factor) => this.figures.find((f) => f.movable)?.zoom(null, factor),
    orbit: (yaw, pitch) => this.figures.find((f) => f.spec.kind === 'space')?.orbit(yaw, pitch),
    sidePanel: () => {
      // Folded by default in presenter view, shown by default elsewhere.
      const presenting = document.documentElement.classList.contains('projector');
      this.element.classList.toggle(presenting ? 'panel-shown' : 'panel-folded');
      this.refresh();
    },
    lecturerControls: () => this.lecturerControls(),
    ask: () => this.caption.ask(),
    blank: () => this.presenter.blank(),
    unblank: () => this.presenter.unblank(),
    blanked: () => this.presenter.blanked,
    tool: (name) => this.presenter.toggle(name),
    clearInk: () => this.presenter.clearInk(),
  };

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
          invalidate: (figure) => this.frame.invalidate(figure),
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
    // First of the page's parts: any part may ask for a frame as it is made.
    this.frame = new PageFrame<S, M>({
      figures: this.figures,
      state: () => this.store.state,
      model: this.model,
      fitted: () => [this.panel.element, this.presenter.caption],
      prepare: (state, model, moved) => {
        if (moved && this.presenter.tools.trail) this.trails.extend(this.figures, model);
        this.showFigures(state, model);
      },
      updatePanel: (state, model) => this.updatePanel(state, model),
      hovered: () => this.panel.hover?.(this.hover),
      busy: () => this.walker.steps?.measuring === true,
      linkPending: () => this.url.pending,
      writeLink: () => this.url.write(),
    });
    this.panel = lesson.panel({
      get: () => this.store.state,
      model: () => this.current(),
      set,
      notice: (message) => shell.notice(message),
      setHover: (id) => this.setHover(id),
      theme: () => shell.theme(),
    });
    this.links = new PageLinks<S, M>({
      lesson,
      store: this.store,
      figures: this.figures,
      practice: () => this.practice,
      restart: (scene) => this.walker.restart(scene),
      notice: (message) => shell.notice(message),
    });
    this.url = this.links.url;
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
        redraw: () => this.frame.redrawAll(),
        linkChanged: () => this.url.schedule(0),
      },
      loaded,
    );
    this.tools = new LessonTools(
      lesson.slug,
      {
        undo: () => this.store.undo(),
        redo: () => this.store.redo(),
        fit: () => this.fit(),
        copyLink: () => void this.links.copyLink(),
        exportPng: () => void this.exportPng(),
        exportSvg: () => this.exportSvg(),
        openHandout: () => this.links.openHandout(),
        lecturerControls: () => this.lecturerControls(),
      },
      () => ({ element: this.element, figureBox: this.figureBox }),
    );

    const figures = h('div', { class: 'stage-figures' });
    this.arrangement = new FigureArrangement<S, M>(lesson, this.figures, figures, () =>
      this.frame.redrawAll(),
    );
    this.figureBox = figures;
    this.presenter = new Presenter(
      figures,
      (tool) => this.toolChanged(tool),
      () => shell.togglePresenter(),
    );
    const dom = buildPageDom({
      slug: lesson.slug,
      title: meta.title,
      toolbar: this.tools.toolbar,
      stage: [this.tools.controlsToggle, this.presenter.caption, figures],
      controls: [
        this.parameter?.element,
        this.walker.steps?.element,
        this.tools.textToggle,
        this.presenter.toolbar,
      ],
      panel: [
        this.practice?.entry,
        this.practice?.practice.element,
        this.walker.sceneGroup,
        this.panel.element,
      ],
      panelResized: () => this.frame.panelResized(),
    });
    this.element = dom.element;
    this.stopLayout = dom.stop;
    this.caption = new StepCaption<S, M>({
      lesson,
      store: this.store,
      walker: this.walker,
      presenter: this.presenter,
      model: this.model,
      panelShown: () => this.element.classList.contains('panel-shown'),
      announce: (text) => shell.announce(text),
      rewrite: () => this.frame.panelAgain(),
    });
    this.panel.element.classList.add('panel-pending');
    // Formula fonts arriving late change widths measured before them: fit again.
    document.fonts?.addEventListener('loadingdone', this.fontsLoaded);
    this.releaseUnseen = holdUnseenWhilePressed(window, () => this.frame.fitSoon());
    for (const issue of loaded.issues) shell.notice(`Ignored from the link: ${issue}.`);
    this.links.applyViews(loaded.views);
    this.unsubscribe = this.store.subscribe(() => {
      this.frame.request();
      this.url.schedule();
    });
    this.frame.request();
    // The link of the state the page opened with is written at once: it is final.
    this.url.write();
  }

  private readonly fontsLoaded = (): void => {
    refitAll(this.panel.element);
    refitAll(this.presenter.caption);
    this.frame.fitSoon();
  };

  /** The panel, the caption, the slider, the steps and Undo/Redo, for a state just drawn. */
  private updatePanel(state: S, model: M): void {
    this.panel.update(model, state);
    if (this.panelPending) {
      this.panelPending = false;
      this.panel.element.classList.remove('panel-pending');
    }
    this.caption.update(state, model);
    this.parameter?.update(state);
    this.walker.update(state);
    this.tools.history(this.store.canUndo, this.store.canRedo);
  }

  /** A presenter tool was switched: redraw what it changes. */
  private toolChanged(tool: PresenterTool | 'blank'): void {
    if (tool === 'ghost') this.ghostModel = this.presenter.tools.ghost ? this.current() : null;
    if (tool === 'trail') this.trails.clear();
    if (tool !== 'blank' && tool !== 'laser' && tool !== 'ink') this.frame.redrawAll();
  }

  /** The model of the current state. */
  current(): M {
    return this.model(this.store.state);
  }

  info(): DrawInfo {
    return { hover: this.hover, thumbnail: false };
  }

  /** Redraws everything after a change of display settings (presenter view changes every size). */
  refresh(): void {
    refitAll(this.panel.element);
    this.frame.refresh();
  }

  setHover(id: string | null): void {
    if (id === this.hover) return;
    this.hover = id;
    this.frame.hoverMoved();
  }

  /** The figures on screen: what an export saves. */
  private shownFigures(): FigureView<S, M>[] {
    return this.figures.filter((figure) => !figure.element.hidden);
  }

  /** Shows and arranges the figures this state's scene declares (their DOM changes once a change of scene). */
  private showFigures(state: S, model: M): void {
    this.arrangement.arrange(
      this.lesson.figuresShown?.(state) ?? null,
      document.documentElement.classList.contains('projector'),
      this.store.scene,
      () => model,
      () => this.shell.theme(),
    );
  }

  /** Resolves when the page is settled (see PageFrame.settled): tests wait on this. */
  settled(): Promise<void> {
    return this.frame.settled();
  }

  /** Where a figure's point is on the screen, and its handle in the figure (a test hook). */
  probe(figure: string, point: readonly number[] | null, id: string | null) {
    return probeFigure(this.figures, figure, point, id);
  }

  /** Each figure's labels as last drawn, with its size: for the overlap check. */
  labelBoxes() {
    return labelBoxesOf(this.figures);
  }

  writeUrl(): void {
    this.url.write();
  }

  lecturerControls(): void {
    this.tools.controlsShown(this.element.classList.toggle('controls-shown'));
    this.refresh();
  }

  fit(): void {
    for (const figure of this.figures) figure.fit();
  }

  async exportPng(): Promise<void> {
    this.frame.drawAllNow();
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
    this.stopLayout();
    this.arrangement.disconnect();
    document.fonts?.removeEventListener('loadingdone', this.fontsLoaded);
    this.releaseUnseen();
    this.frame.stop();
    for (const figure of this.figures) figure.destroy();
    this.presenter.destroy();
    this.panel.destroy?.();
  }
}
