/**
 * Hosts one lesson: its figures, the construction controls, its side panel
 * and caption, wired to one store of its state. The frame that keeps them in
 * step is `pageFrame.ts`; the caption is `stepCaption.ts`; the page's own
 * buttons are `lessonTools.ts`.
 */
import { presenting } from './settings';
import { holdUnseenWhilePressed } from '../render/unseen';
import type { Theme } from '../render/theme';
import { ParameterControl } from './parameterControl';
import { memoize } from './derive';
import type { PageKeys, PresenterTool } from './keyTarget';
import { buildPageDom } from './pageDom';
import type { AnyLesson } from './lesson';
import { LessonStore, type Loaded } from './lessonState';
import { LessonTools } from './lessonTools';
import { PageLinks } from './pageLinks';
import type { LessonMeta } from './meta';
import { PageFigures } from './pageFigures';
import { PageFrame } from './pageFrame';
import { PagePanel } from './pagePanel';
import { pageKeys } from './pageKeys';
import { Presenter } from './presenter';
import { ScriptWalker } from './scriptWalker';
import { StepCaption } from './stepCaption';
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
  /** The lesson's figures, as the scene shows them (pageFigures.ts). */
  readonly figures: PageFigures<S, M>;
  readonly model: (state: S) => M;
  private readonly panel: PagePanel<S, M>;
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
  /** Undoes holdUnseenWhilePressed (unseen.ts). */
  private readonly releaseUnseen: () => void;
  private readonly unsubscribe: () => void;
  /** Stops watching the page's layout (pageDom.ts). */
  private readonly stopLayout: () => void;
  readonly presenter: Presenter;

  /** What the keys and the clicker do on this page (pageKeys.ts). */
  readonly keys: PageKeys;

  constructor(
    readonly meta: LessonMeta,
    readonly lesson: AnyLesson,
    loaded: Loaded<S>,
    shell: Shell,
  ) {
    this.store = new LessonStore<S>(lesson, loaded.state, loaded.scene);
    this.model = memoize((state: S) => lesson.derive(state) as M);
    const set = (next: S, options?: { coalesce?: string; windowMs?: number; record?: boolean }) =>
      this.store.set(next, options);
    this.figures = new PageFigures<S, M>({
      lesson,
      store: this.store,
      model: this.model,
      theme: () => shell.theme(),
      announce: (text) => shell.announce(text),
      url: () => this.url,
      invalidate: (figure) => this.frame.invalidate(figure),
      redrawAll: () => this.frame.redrawAll(),
      hoverMoved: () => this.frame.hoverMoved(),
      shown: () => this.presenter.shown(),
      presenting,
      practice: () => this.practice,
    });
    // First of the page's parts: any part may ask for a frame as it is made.
    this.frame = new PageFrame<S, M>({
      figures: this.figures.views,
      state: () => this.store.state,
      model: this.model,
      fitted: () => [this.panel.element, this.presenter.caption],
      prepare: (state, model, moved) =>
        this.figures.prepare(state, model, moved, this.presenter.tools.trail),
      updatePanel: (state, model) => this.updatePanel(state, model),
      hovered: () => this.panel.hover(this.figures.hovered),
      busy: () => this.walker.steps?.measuring === true,
      linkPending: () => this.url.pending,
      writeLink: () => this.url.write(),
    });
    this.panel = new PagePanel<S, M>(lesson, {
      get: () => this.store.state,
      model: () => this.figures.current(),
      set,
      notice: (message) => shell.notice(message),
      setHover: (id) => this.figures.setHover(id),
      theme: () => shell.theme(),
    });
    this.links = new PageLinks<S, M>({
      lesson,
      store: this.store,
      figures: this.figures.views,
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
      pauseAtSceneEnd: () => !presenting(),
    });
    this.practice = PracticeHost.of<S>(
      {
        lesson,
        store: this.store,
        walker: this.walker,
        element: () => this.element,
        figureBox: () => this.figures.element,
        shownFigureIds: () => this.figures.shown().map((f) => f.spec.id),
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
        exportPng: () => void this.figures.exportPng(() => this.frame.drawAllNow()),
        exportSvg: () => this.figures.exportSvg(),
        openHandout: () => this.links.openHandout(),
        lecturerControls: () => this.lecturerControls(),
      },
      () => ({ element: this.element, figureBox: this.figures.element }),
    );
    this.presenter = new Presenter(
      this.figures.element,
      (tool) => this.toolChanged(tool),
      () => shell.togglePresenter(),
    );
    const dom = buildPageDom({
      slug: lesson.slug,
      title: meta.title,
      toolbar: this.tools.toolbar,
      stage: [this.tools.controlsToggle, this.presenter.caption, this.figures.element],
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
    // Formula fonts arriving late change widths measured before them: fit again.
    document.fonts?.addEventListener('loadingdone', this.fontsLoaded);
    this.releaseUnseen = holdUnseenWhilePressed(window, () => this.frame.fitSoon());
    for (const issue of loaded.issues) shell.notice(`Ignored from the link: ${issue}.`);
    this.links.applyViews(loaded.views);
    this.unsubscribe = this.store.subscribe(() => {
      this.frame.request();
      this.url.schedule();
    });
    this.keys = pageKeys({
      store: this.store,
      walker: this.walker,
      parameter: this.parameter,
      figures: this.figures,
      presenter: this.presenter,
      caption: this.caption,
      element: this.element,
      refresh: () => this.refresh(),
      lecturerControls: () => this.lecturerControls(),
    });
    this.frame.request();
    // The link of the state the page opened with is written at once: it is final.
    this.url.write();
  }

  private readonly fontsLoaded = (): void => {
    this.panel.refit();
    this.presenter.captionBox.refit();
    this.frame.fitSoon();
  };

  /** The panel, the caption, the slider, the steps and Undo/Redo, for a state just drawn. */
  private updatePanel(state: S, model: M): void {
    this.panel.update(model, state);
    this.caption.update(state, model);
    this.parameter?.update(state);
    this.walker.update(state);
    this.tools.history(this.store.canUndo, this.store.canRedo);
  }

  /** A presenter tool was switched: redraw what it changes. */
  private toolChanged(tool: PresenterTool | 'blank'): void {
    this.figures.toolChanged(tool, tool !== 'blank' && this.presenter.tools[tool] === true);
  }

  /** Redraws everything after a change of display settings (presenter view changes every size). */
  refresh(): void {
    this.panel.refit();
    this.frame.refresh();
  }

  /** Resolves when the page is settled (see PageFrame.settled): tests wait on this. */
  settled(): Promise<void> {
    return this.frame.settled();
  }

  /** Where a figure's point is on the screen, and its handle in the figure (a test hook). */
  probe(figure: string, point: readonly number[] | null, id: string | null) {
    return this.figures.probe(figure, point, id);
  }

  /** Each figure's labels as last drawn, with its size: for the overlap check. */
  labelBoxes() {
    return this.figures.labelBoxes();
  }

  writeUrl(): void {
    this.url.write();
  }

  lecturerControls(): void {
    this.tools.controlsShown(this.element.classList.toggle('controls-shown'));
    this.refresh();
  }

  fit(): void {
    this.figures.fit();
  }

  destroy(): void {
    this.practice?.stopWalk();
    // By now the address bar may already show another page: only remember
    // (and a write still pending sees the new address and leaves it alone).
    this.url.close();
    this.parameter?.stop();
    this.unsubscribe();
    this.stopLayout();
    document.fonts?.removeEventListener('loadingdone', this.fontsLoaded);
    this.releaseUnseen();
    this.frame.stop();
    this.figures.destroy();
    this.presenter.destroy();
    this.panel.destroy();
  }
}
