/**
 * The figures of a lesson page: one FigureView for each figure the lesson
 * declares, and the host they draw for (the hovered point, the presenter's
 * ghost and trails, an exercise's marks), arranged as the scene shows them,
 * and what the page does with all of them at once: fit them, export them,
 * and answer the tests' probes.
 */
import type { Shown } from '../render/painter';
import type { Theme } from '../render/theme';
import { h } from './dom';
import { download, figuresToPng, figuresToSvg } from './exportFigure';
import { FigureArrangement } from './figureArrangement';
import { FigureView } from './figureView';
import type { PresenterTool } from './keyTarget';
import type { AnyLesson, DrawInfo } from './lesson';
import type { LessonStore } from './lessonState';
import { labelBoxesOf, probeFigure } from './pageProbes';
import type { PracticeHost } from './practiceHost';
import { Trails } from './trails';
import type { UrlSync } from './urlSync';

/** What the figures need of the page round them. */
export interface FiguresPage<S, M> {
  readonly lesson: AnyLesson;
  readonly store: LessonStore<S>;
  readonly model: (state: S) => M;
  theme(): Theme;
  announce(text: string): void;
  /** The page's link: a moved view belongs in it, a drag holds it until its end. */
  url(): UrlSync;
  /** This figure needs drawing in the next frame. */
  invalidate(figure: FigureView<S, M>): void;
  /** Every figure needs drawing afresh. */
  redrawAll(): void;
  /** The hovered point changed: the figures and the panel mark it. */
  hoverMoved(): void;
  /** What the presenter lets figures show. */
  shown(): Shown;
  /** Whether presenter view is on (it arranges the figures its own way). */
  presenting(): boolean;
  /** The lesson's exercises, if it has any: their marks and guesses are on the figures. */
  practice(): PracticeHost<S> | undefined;
}

export class PageFigures<S, M> {
  readonly views: FigureView<S, M>[];
  /** The figures' box, and the figures in it as the scene shows and arranges them. */
  readonly element: HTMLElement;
  private readonly arrangement: FigureArrangement<S, M>;
  private hover: string | null = null;
  /** The model kept as a faint ghost (presenter tool), or null. */
  private ghostModel: M | null = null;
  /** The trail of each figure's moving point (presenter tool). */
  private readonly trails = new Trails();

  constructor(private readonly page: FiguresPage<S, M>) {
    const { store, lesson } = page;
    this.views = lesson.figures.map(
      (spec) =>
        new FigureView<S, M>(spec, {
          get: () => store.state,
          model: () => this.current(),
          set: (next, options) => store.set(next, options),
          theme: () => page.theme(),
          info: () => this.info(),
          setHover: (id) => this.setHover(id),
          announce: (text) => page.announce(text),
          invalidate: (figure) => page.invalidate(figure),
          viewChanged: () => page.url().schedule(300),
          hold: () => page.url().hold(),
          settle: () => page.url().write(),
          shown: () => page.shown(),
          ghost: () => this.ghostModel,
          trail: (figure) => this.trails.of(figure),
          marks: (figure) => page.practice()?.practice.marks(figure) ?? [],
          tap: (figure, at) => page.practice()?.practice.tap(figure, at) ?? false,
        }),
    );
    this.element = h('div', { class: 'stage-figures' });
    this.arrangement = new FigureArrangement<S, M>(lesson, this.views, this.element, () =>
      page.redrawAll(),
    );
  }

  /** The model of the current state. */
  current(): M {
    return this.page.model(this.page.store.state);
  }

  /** The point under the pointer, as the figures draw it. */
  get hovered(): string | null {
    return this.hover;
  }

  info(): DrawInfo {
    return { hover: this.hover, thumbnail: false };
  }

  setHover(id: string | null): void {
    if (id === this.hover) return;
    this.hover = id;
    this.page.hoverMoved();
  }

  /**
   * Before a state is drawn: the trails grow by where the point moved (when
   * the state moved and the presenter's trail is on), and the figures this
   * state's scene declares are shown and arranged (their DOM changes once a
   * change of scene).
   */
  prepare(state: S, model: M, moved: boolean, trailOn: boolean): void {
    if (moved && trailOn) this.trails.extend(this.views, model);
    this.arrangement.arrange(
      this.page.lesson.figuresShown?.(state) ?? null,
      this.page.presenting(),
      this.page.store.scene,
      () => model,
      () => this.page.theme(),
    );
  }

  /** A presenter tool was switched on (`on`) or off: keep the ghost, clear the trail, redraw. */
  toolChanged(tool: PresenterTool | 'blank', on: boolean): void {
    if (tool === 'ghost') this.ghostModel = on ? this.current() : null;
    if (tool === 'trail') this.trails.clear();
    if (tool !== 'blank' && tool !== 'laser' && tool !== 'ink') this.page.redrawAll();
  }

  /** The figures on screen: what an export saves. */
  shown(): FigureView<S, M>[] {
    return this.views.filter((figure) => !figure.element.hidden);
  }

  fit(): void {
    for (const figure of this.views) figure.fit();
  }

  /** Saves the figures on screen as one PNG (drawn first with `drawAll`). */
  async exportPng(drawAll: () => void): Promise<void> {
    drawAll();
    const blob = await figuresToPng(this.shown(), this.page.theme());
    download(blob, `spline-lab-${this.page.lesson.slug}.png`);
  }

  /** Saves the figures on screen as one SVG, drawn from the current model. */
  exportSvg(): void {
    const svg = figuresToSvg(this.shown(), this.current(), this.page.theme(), this.info());
    download(new Blob([svg], { type: 'image/svg+xml' }), `spline-lab-${this.page.lesson.slug}.svg`);
  }

  /** Where a figure's point is on the screen, and its handle in the figure (a test hook). */
  probe(figure: string, point: readonly number[] | null, id: string | null) {
    return probeFigure(this.views, figure, point, id);
  }

  /** Each figure's labels as last drawn, with its size: for the overlap check. */
  labelBoxes() {
    return labelBoxesOf(this.views);
  }

  destroy(): void {
    this.arrangement.disconnect();
    for (const figure of this.views) figure.destroy();
  }
}
