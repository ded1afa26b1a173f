/**
 * One canvas of a lesson with its handles: it puts together the figure's
 * size, its view (fitted or the user's), the backdrop under the canvas and
 * the handles' interaction, and draws the lesson's figure over them, only
 * when the picture would change.
 */
import { attachPointer, type Screen } from '../interact/pointer';
import { OrbitCamera } from '../render/orbitCamera';
import { Painter, type Shown, SHOW_ALL } from '../render/painter';
import { type LabelBox, glyphBox } from '../render/labels';
import type { Projection } from '../render/projection';
import type { DrawingSurface } from '../render/surface';
import type { Theme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { setClass } from './dom';
import { DrawnFrom } from './drawnFrom';
import { FigureBackdrop, paintBackdrop } from './figureBackdrop';
import { drawGhost } from './figureGhost';
import { FigureHandles } from './figureHandles';
import { type FigureMark, drawMarks } from './figureMarks';
import { FigureSize, stripHeight } from './figureSize';
import type { DrawInfo, FigureSpec, Point } from './lesson';
import { ViewFit } from './viewFit';

export { drawHandles, plainLabel } from '../render/handles';
export type { FigureMark } from './figureMarks';

/** What a figure needs from the page that hosts it. */
export interface FigureHost<S, M> {
  get(): S;
  model(): M;
  set(next: S, options: { coalesce?: string; windowMs?: number; record?: boolean }): void;
  theme(): Theme;
  info(): DrawInfo;
  setHover(id: string | null): void;
  announce(text: string): void;
  /** This figure needs drawing (its view or its size changed, or a handle took focus). */
  invalidate(figure: FigureView<S, M>): void;
  /** The user moved this figure's view: it belongs in the link. */
  viewChanged(): void;
  /** A drag began: the link waits for its end. */
  hold(): void;
  /** A gesture ended: the state is final for now (write the link at once). */
  settle(): void;
  /** What the presenter lets figures show. */
  shown(): Shown;
  /** A model to draw faintly under the current one (presenter's ghost), or null. */
  ghost(): M | null;
  /** The trail of this figure's moving point (presenter tool), or null. */
  trail(figure: string): readonly Point[] | null;
  /** Marks drawn over this figure (an exercise's guess and answer). */
  marks(figure: string): readonly FigureMark[];
  /** A tap or click on empty space, in the figure's coordinates: true if it was taken (a guess). */
  tap(figure: string, at: Point): boolean;
}

/** One canvas of a lesson, sharp at any devicePixelRatio, with its handles. */
export class FigureView<S, M> {
  readonly element: HTMLElement;
  readonly canvas: HTMLCanvasElement;
  readonly view: Projection;
  private readonly handles: FigureHandles<S, M>;
  private readonly backdrop: FigureBackdrop;
  private readonly size: FigureSize;
  private readonly viewFit: ViewFit<S, M>;
  private readonly detach: () => void;
  /** Where the last frame put its labels (screen pixels): for the overlap check. */
  labels: readonly LabelBox[] = [];
  /** The last frame's painter, with its ink: which labels a stroke runs through, asked by tests. */
  private painted: Painter | null = null;
  private readonly drawnFrom: DrawnFrom<S, M>;

  constructor(
    readonly spec: FigureSpec<S, M>,
    private readonly host: FigureHost<S, M>,
  ) {
    this.drawnFrom = new DrawnFrom(spec, host);
    this.view = spec.kind === 'space' ? new OrbitCamera(spec.camera) : new Viewport();
    this.element = document.createElement('div');
    setClass(this.element, `figure figure-${spec.kind}`);
    this.element.dataset.figure = spec.id;
    if (spec.height) stripHeight(this.element, spec.height, host.theme());
    if (spec.aspect) this.element.style.aspectRatio = String(spec.aspect);
    this.canvas = document.createElement('canvas');
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', spec.title);
    this.canvas.dataset.figure = spec.id;
    this.backdrop = new FigureBackdrop(this.view, spec.kind);
    const layer = document.createElement('div');
    setClass(layer, 'handle-layer');
    this.element.append(this.backdrop.element, this.canvas, layer);
    const handles = new FigureHandles(spec, host, this.view, this.canvas, layer, () =>
      this.redrawSoon(),
    );
    this.handles = handles;
    this.size = new FigureSize(this.element, this.canvas, this.view, () => this.redrawSoon());
    this.viewFit = new ViewFit(spec, host, this.view, this.size, () => this.redrawSoon());
    const movable = this.viewFit.movable;
    this.detach = attachPointer(this.canvas, {
      pick: (at, type) => handles.pick(at, type),
      dragStart: (id, at) => handles.dragStart(id, at),
      dragMove: (_id, at, shift) => handles.dragMove(at, shift),
      dragEnd: () => handles.dragEnd(),
      hover: (at) => handles.hover(at),
      pan: movable ? (dx, dy) => this.viewFit.move(() => this.view.dragBy(dx, dy)) : undefined,
      zoom: movable ? (at, factor) => this.zoom(at, factor) : undefined,
      add: spec.addPoint ? (at) => handles.add(at) : undefined,
      remove: spec.removeHandle ? (id) => handles.remove(id) : undefined,
      tap: (at) => handles.tap(at),
      tapHandle: (id, type, at) => handles.tapHandle(id, type, at),
    });
    if (spec.removeHandle) this.element.append(handles.deleteButton);
  }

  destroy(): void {
    this.detach();
    this.size.disconnect();
  }

  /** Can the user move this figure's view (and so may the link carry it)? */
  get movable(): boolean {
    return this.viewFit.movable;
  }

  /** Fits the view to the lesson's bounds (key 0, a preset, first show). */
  fit(): void {
    this.viewFit.fit();
  }

  zoom(at: Screen | null, factor: number): void {
    if (!this.movable) return;
    this.viewFit.move(() =>
      this.view.zoomAt(at ?? [this.view.width / 2, this.view.height / 2], factor),
    );
  }

  /** Turns a figure in space by whole degrees (keyboard orbit). */
  orbit(yaw: number, pitch: number): void {
    if (this.view instanceof OrbitCamera) {
      const camera = this.view;
      this.viewFit.move(() => camera.orbit(yaw, pitch));
    }
  }

  /** The view for the link, when the user has moved it; else null (the link fits). */
  viewText(): string | null {
    return this.viewFit.text();
  }

  /** Takes the view from a link; false if it could not be read (then it fits). */
  applyView(text: string | null): boolean {
    return this.viewFit.apply(text);
  }

  /**
   * Draws the figure for `model`, unless it would draw the very picture on its
   * canvas now (see `FigureSpec.drawnFrom`): a plot of basis functions is not
   * drawn again while a point it does not depend on is dragged. `fresh`
   * draws whatever it was drawn from (settings changed).
   */
  draw(model: M, fresh = false): void {
    const theme = this.host.theme();
    if (this.spec.height) stripHeight(this.element, this.spec.height, theme);
    const resized = this.size.sizeCanvas();
    if (resized) this.viewFit.resized();
    if (this.drawnFrom.unchanged(model, theme, fresh || resized)) return;
    this.viewFit.fitIfDue(model, theme);
    const ctx = this.canvas.getContext('2d');
    if (!ctx) return;
    const dpr = window.devicePixelRatio || 1;
    this.backdrop.draw(this.size, theme);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    this.painted = this.render(ctx, model, theme, this.host.info(), this.host.shown(), false);
    this.labels = this.painted.labels;
    this.handles.syncKeys();
  }

  /** What lies under the figure's drawing: its background, and a geometry figure's grid. */
  paintBackdrop(surface: DrawingSurface, theme: Theme): void {
    paintBackdrop(surface, this.view, this.spec.kind, theme);
  }

  /** The figure's view changed (zoom, pan, a drag's end): draw it in the next frame. */
  private redrawSoon(): void {
    this.drawnFrom.forget();
    this.host.invalidate(this);
  }

  /** The last frame's labels that a stroke or a point runs through, with what does (for tests). */
  crossedLabels(): string[] {
    const painter = this.painted;
    if (!painter) return [];
    return painter.labels.flatMap((label) => {
      const through = label.boxed ? null : painter.ink.crossing(glyphBox(label));
      return through ? [`${through} through “${label.text}”`] : [];
    });
  }

  /** Draws the figure to any surface at the current view: the canvas, an SVG export, a test recording. */
  render(
    surface: DrawingSurface,
    model: M,
    theme: Theme,
    info: DrawInfo,
    shown: Shown = SHOW_ALL,
    /** Draw the background and the grid too (false on the canvas: its backdrop has them). */
    backdrop = true,
  ): Painter {
    if (backdrop) {
      if (info.thumbnail) new Painter(surface, this.view, theme, shown).clear();
      else this.paintBackdrop(surface, theme);
    }
    const painter = new Painter(surface, this.view, theme, shown);
    if (this.spec.kind === 'geometry') painter.gridAxesAsInk();
    if (!info.thumbnail) {
      const ghost = this.host.ghost();
      if (ghost !== null) drawGhost(surface, this.view, this.spec, ghost, theme, info);
    }
    painter.holdLabels();
    this.spec.draw(painter, model, info);
    const trail = info.thumbnail ? null : this.host.trail(this.spec.id);
    if (trail && trail.length > 1)
      painter.polyline(trail, { color: theme.accent, width: theme.sizes.line, alpha: 0.8 });
    if (!info.thumbnail) drawMarks(painter, this.host.marks(this.spec.id), theme);
    const handles = this.handles.of(model);
    if (info.thumbnail) {
      painter.placeLabels();
      return painter;
    }
    this.handles.draw(painter, handles, info.hover);
    this.spec.drawOver?.(painter, model, info);
    painter.placeLabels();
    return painter;
  }

  /** Where handle `id` is now, in the figure's coordinates, or null. */
  handlePosition(id: string): Point | null {
    return this.handles.position(id);
  }
}
