import { sameValues } from '../kit/memoOn';
import { fitFigure, fitPadding } from './headless';
import { HandleDrag, type KeySize, keyStep, nearestHandle } from '../interact/handleDrag';
import { HandleKeys } from '../interact/handleKeys';
import { attachPointer, hitTolerance, type Screen } from '../interact/pointer';
import { OrbitCamera } from '../render/orbitCamera';
import { Painter, type Shown, SHOW_ALL } from '../render/painter';
import { drawHandles, plainLabel } from '../render/handles';
import { type LabelBox, glyphBox } from '../render/labels';
import type { Projection } from '../render/projection';
import type { DrawingSurface } from '../render/surface';
import { SvgContext } from '../render/svgContext';
import type { Theme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { fmtPoint, setClass, setHidden, setText } from './dom';
import type { DrawInfo, FigureSpec, Handle, Point } from './lesson';
import { SpokenNames } from './spokenNames';

export { drawHandles, plainLabel } from '../render/handles';

/** A point marked over a figure: a guess (a cross), the answer (a ring) or a target (a ring with a dot), with a short label. */
export interface FigureMark {
  kind: 'guess' | 'answer' | 'target';
  at: Point;
  label: string;
}

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

let dragSerial = 0;

const SVG_NS = 'http://www.w3.org/2000/svg';

/** One canvas of a lesson, sharp at any devicePixelRatio, with its handles. */
export class FigureView<S, M> {
  readonly element: HTMLElement;
  readonly canvas: HTMLCanvasElement;
  readonly view: Projection;
  private readonly keys: HandleKeys;
  private readonly detach: () => void;
  private readonly resizeObserver: ResizeObserver;
  /** The handles of the model last drawn, computed once per model. */
  private handles: Handle[] = [];
  private handlesOf: M | null = null;
  private names: string[] = [];
  private readonly spokenNames = new SpokenNames();
  private dragging: { drag: HandleDrag; key: string } | null = null;
  /** The handle a finger tapped: its delete button is shown. */
  private chosen: string | null = null;
  private readonly deleteButton: HTMLButtonElement;
  private focused: string | null = null;
  private fitted = false;
  /** The user moved the view: keep it (and put it in the link), unless asked to fit. */
  private userView = false;
  private size = { width: 0, height: 0 };
  /** Where the last frame put its labels (screen pixels): for the overlap check. */
  labels: readonly LabelBox[] = [];
  /** The last frame's painter, with its ink: which labels a stroke runs through, asked by tests. */
  private painted: Painter | null = null;
  /** What the canvas's picture was drawn from (`drawnFromNow`), or null. */
  private drawnFrom: readonly unknown[] | null = null;
  /** The figure's box as last observed (CSS pixels), or null before the first observation. */
  private box: { width: number; height: number } | null = null;
  /**
   * Under the canvas: the background and a geometry figure's grid, drawn again
   * only when the size, the view or the theme changes (`backdropFrom` holds
   * those it was drawn for). A drag frame then rasterises what moved, and not a fill and a
   * grid over the whole figure that did not. It is vector drawing, not a
   * second canvas: Chromium hands the compositor a copy of every canvas layer
   * on every frame, changed or not (a static canvas under a drawn one: 3 → 6
   * ms a frame), while the page's own drawing is rastered again only when it
   * changes.
   */
  private readonly backdrop: SVGSVGElement;
  private backdropFrom: readonly unknown[] = [];

  constructor(
    readonly spec: FigureSpec<S, M>,
    private readonly host: FigureHost<S, M>,
  ) {
    this.view = spec.kind === 'space' ? new OrbitCamera(spec.camera) : new Viewport();
    this.element = document.createElement('div');
    setClass(this.element, `figure figure-${spec.kind}`);
    this.element.dataset.figure = spec.id;
    this.element.style.flexGrow = String(spec.weight ?? 1);
    if (spec.height) this.stripHeight(host.theme());
    if (spec.aspect) this.element.style.aspectRatio = String(spec.aspect);
    this.canvas = document.createElement('canvas');
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', spec.title);
    this.canvas.dataset.figure = spec.id;
    this.backdrop = document.createElementNS(SVG_NS, 'svg');
    this.backdrop.setAttribute('class', 'figure-backdrop');
    this.backdrop.setAttribute('aria-hidden', 'true');
    const layer = document.createElement('div');
    setClass(layer, 'handle-layer');
    this.element.append(this.backdrop, this.canvas, layer);
    this.keys = new HandleKeys(layer, {
      move: (id, delta, size) => this.keyMove(id, delta, size),
      remove: spec.removeHandle ? (id) => this.remove(id) : undefined,
      focus: (id) => {
        this.focused = id;
        this.redrawSoon();
      },
    });
    const movable = spec.kind === 'geometry' || spec.kind === 'space';
    this.detach = attachPointer(this.canvas, {
      pick: (at, type) => this.pick(at, type),
      dragStart: (id, at) => this.dragStart(id, at),
      dragMove: (_id, at, shift) => this.dragMove(at, shift),
      dragEnd: () => this.dragEnd(),
      hover: (at) => this.hover(at),
      pan: movable ? (dx, dy) => this.moveView(() => this.view.dragBy(dx, dy)) : undefined,
      zoom: movable ? (at, factor) => this.zoom(at, factor) : undefined,
      add: spec.addPoint ? (at) => this.add(at) : undefined,
      remove: spec.removeHandle ? (id) => this.remove(id) : undefined,
      tap: (at) => {
        this.choose(null);
        if (this.spec.kind !== 'space') host.tap(spec.id, this.view.toWorld(at));
      },
      // A guess may be right next to a point: the tap is the guess, if one is asked for.
      tapHandle: (id, type, at) => {
        const guessed = this.spec.kind !== 'space' && host.tap(spec.id, this.view.toWorld(at));
        this.choose(guessed || type === 'mouse' ? null : id);
      },
    });
    // A finger has no right-click or Delete key: a tapped point offers its own delete button.
    this.deleteButton = document.createElement('button');
    this.deleteButton.type = 'button';
    setClass(this.deleteButton, 'delete-point');
    setHidden(this.deleteButton, true);
    this.deleteButton.addEventListener('click', () => {
      if (this.chosen) this.remove(this.chosen);
      this.choose(null);
    });
    if (spec.removeHandle) this.element.append(this.deleteButton);
    this.resizeObserver = new ResizeObserver(([entry]) => {
      // The size is read here, once per change, never while drawing a frame.
      this.box = { width: entry.contentRect.width, height: entry.contentRect.height };
      this.redrawSoon();
    });
    this.resizeObserver.observe(this.element);
  }

  destroy(): void {
    this.detach();
    this.resizeObserver.disconnect();
  }

  /** Can the user move this figure's view (and so may the link carry it)? */
  get movable(): boolean {
    return this.spec.kind === 'geometry' || this.spec.kind === 'space';
  }

  private moveView(change: () => void): void {
    change();
    this.userView = true;
    this.redrawSoon();
    this.host.viewChanged();
  }

  /** Fits the view to the lesson's bounds (key 0, a preset, first show). */
  fit(): void {
    const changed = this.userView;
    this.userView = false;
    this.fitted = false;
    this.redrawSoon();
    if (changed) this.host.viewChanged();
  }

  zoom(at: Screen | null, factor: number): void {
    if (!this.movable) return;
    this.moveView(() =>
      this.view.zoomAt(at ?? [this.view.width / 2, this.view.height / 2], factor),
    );
  }

  /** Turns a figure in space by whole degrees (keyboard orbit). */
  orbit(yaw: number, pitch: number): void {
    if (this.view instanceof OrbitCamera) {
      const camera = this.view;
      this.moveView(() => camera.orbit(yaw, pitch));
    }
  }

  /**
   * The view for the link, when the user has moved it; else null (the link
   * fits). A figure in space turned and then fitted keeps its angles: the
   * link says them, and the fit follows on whatever screen opens it.
   */
  viewText(): string | null {
    if (!this.movable) return null;
    if (this.userView) return this.view.encode();
    return this.view instanceof OrbitCamera ? this.view.encodeAngles(this.spec.camera) : null;
  }

  /** Takes the view from a link; false if it could not be read (then it fits). */
  applyView(text: string | null): boolean {
    if (text === null || !this.movable) {
      // A link without a view opens fitted to the points it brings, as a fresh page does
      // (the view fitted to the last points could leave the new ones off screen).
      this.fit();
      return text === null;
    }
    // Fit first, so a camera read from the link has the distance that fits the scene.
    this.sizeCanvas();
    this.applyFit(this.host.model(), this.host.theme());
    // Angles only: turned, then fitted to the scene on this screen.
    if (this.view instanceof OrbitCamera && this.view.decodeAngles(text)) {
      this.userView = false;
      this.fitted = false;
      this.redrawSoon();
      return true;
    }
    const ok = this.view.decode(text);
    this.userView = ok;
    this.fitted = true;
    this.redrawSoon();
    return ok;
  }

  private applyFit(model: M, theme: Theme): void {
    const padding = fitPadding(this.spec.kind, theme, this.view.width, this.view.height);
    fitFigure(this.view, this.spec, model, theme, padding);
    this.fitted = true;
  }

  /** A strip of fixed height, taller on the projector as its text and handles are. */
  private stripHeight(theme: Theme): void {
    const height = `${Math.round(this.spec.height! * (theme.sizes.strip ?? 1))}px`;
    if (this.element.style.minHeight === height) return;
    this.element.style.flex = `0 0 ${height}`;
    this.element.style.minHeight = height;
  }

  /** Sizes the canvas to its box (device pixels); true if the size changed. */
  private sizeCanvas(): boolean {
    const rect = this.box ?? this.element.getBoundingClientRect();
    const width = Math.max(1, Math.round(rect.width));
    const height = Math.max(1, Math.round(rect.height));
    const dpr = window.devicePixelRatio || 1;
    const changed =
      this.canvas.width !== Math.round(width * dpr) ||
      this.canvas.height !== Math.round(height * dpr);
    if (changed) {
      this.canvas.width = Math.round(width * dpr);
      this.canvas.height = Math.round(height * dpr);
      this.canvas.style.width = `${width}px`;
      this.canvas.style.height = `${height}px`;
    }
    if (width !== this.size.width || height !== this.size.height) {
      this.size = { width, height };
      this.view.resize(width, height);
      return true;
    }
    return changed;
  }

  /**
   * Draws the figure for `model`, unless it would draw the very picture on its
   * canvas now (see `FigureSpec.drawnFrom`): a plot of basis functions is not
   * drawn again while a point it does not depend on is dragged. `fresh`
   * draws whatever it was drawn from (settings changed).
   */
  draw(model: M, fresh = false): void {
    const theme = this.host.theme();
    if (this.spec.height) this.stripHeight(theme);
    const resized = this.sizeCanvas();
    if (resized && !this.userView) this.fitted = false;
    const from = this.drawnFromNow(model, theme);
    if (!fresh && !resized && from && this.drawnFrom && sameValues(from, this.drawnFrom)) return;
    this.drawnFrom = from;
    const alwaysFit = this.spec.kind === 'plot' || this.spec.kind === 'drawing';
    if (!this.fitted || alwaysFit) this.applyFit(model, theme);
    const ctx = this.canvas.getContext('2d');
    if (!ctx) return;
    const dpr = window.devicePixelRatio || 1;
    this.drawBackdrop(theme);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    this.painted = this.render(ctx, model, theme, this.host.info(), this.host.shown(), false);
    this.labels = this.painted.labels;
    this.syncKeys();
  }

  /** The background and the grid under the canvas, if the size, the view or the theme changed. */
  private drawBackdrop(theme: Theme): void {
    const { width, height } = this.size;
    const grid = this.spec.kind === 'geometry';
    // A grid moves with the view: where two of its points land says where it all does.
    const view = grid ? [...this.view.toScreen([0, 0]), ...this.view.toScreen([1, 1])] : [];
    const from = [width, height, theme, ...view];
    if (sameValues(from, this.backdropFrom)) return;
    this.backdropFrom = from;
    const svg = new SvgContext();
    this.paintBackdrop(svg, theme);
    // Markup the SvgContext wrote from the view's numbers and the theme's colours (escaped).
    const drawn = new DOMParser().parseFromString(svg.toSvg(width, height), 'image/svg+xml');
    for (const [name, value] of [
      ['width', width],
      ['height', height],
    ] as const)
      this.backdrop.setAttribute(name, String(value));
    this.backdrop.setAttribute('viewBox', `0 0 ${width} ${height}`);
    this.backdrop.replaceChildren(
      ...[...drawn.documentElement.childNodes].map((node) => document.importNode(node, true)),
    );
  }

  /** What lies under the figure's drawing: its background, and a geometry figure's grid. */
  paintBackdrop(surface: DrawingSurface, theme: Theme): void {
    const painter = new Painter(surface, this.view, theme, SHOW_ALL);
    painter.clear();
    if (this.spec.kind === 'geometry') painter.grid();
  }

  /**
   * What the picture is drawn from now, when the figure says (else null: it is
   * drawn every frame): its own values, and the theme, the pointer's hover
   * and the step. A ghost, a trail or practice marks are drawn every time.
   */
  private drawnFromNow(model: M, theme: Theme): readonly unknown[] | null {
    const own = this.spec.drawnFrom?.(model);
    if (!own) return null;
    const id = this.spec.id;
    if (this.host.ghost() !== null || this.host.trail(id) || this.host.marks(id).length)
      return null;
    const { curve, labels, numbers } = this.host.shown();
    return [theme, this.host.info().hover, curve, labels, numbers, ...own];
  }

  /** The figure's view changed (zoom, pan, a drag's end): draw it in the next frame. */
  private redrawSoon(): void {
    this.drawnFrom = null;
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

  /** The presenter's ghost: the kept model drawn faintly, without labels or handles. */
  private drawGhost(surface: DrawingSurface, theme: Theme, info: DrawInfo): void {
    const ghost = this.host.ghost();
    if (ghost === null) return;
    surface.save();
    // Every stroke sets its own alpha: a faint palette makes the ghost faint.
    const faint: Theme = {
      ...theme,
      curve: theme.curveFaint,
      ink: theme.curveFaint,
      polygon: theme.curveFaint,
      accent: theme.curveFaint,
      palette: theme.palette.map(() => theme.curveFaint),
    };
    const painter = new Painter(surface, this.view, faint, {
      curve: true,
      labels: false,
      numbers: false,
    });
    this.spec.draw(painter, ghost, info);
    surface.restore();
  }

  private handlesFor(model: M): Handle[] {
    if (this.handlesOf !== model) {
      this.handles = this.spec.handles?.(model) ?? [];
      this.handlesOf = model;
      this.names = this.spokenNames.of(this.handles);
    }
    return this.handles;
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
    if (!info.thumbnail) this.drawGhost(surface, theme, info);
    painter.holdLabels();
    this.spec.draw(painter, model, info);
    const trail = info.thumbnail ? null : this.host.trail(this.spec.id);
    if (trail && trail.length > 1)
      painter.polyline(trail, { color: theme.accent, width: theme.sizes.line, alpha: 0.8 });
    if (!info.thumbnail) drawMarks(painter, this.host.marks(this.spec.id), theme);
    const handles = this.handlesFor(model);
    if (info.thumbnail) {
      painter.placeLabels();
      return painter;
    }
    drawHandles(painter, handles, (handle) =>
      this.dragging?.drag.id === handle.id
        ? 'drag'
        : this.focused === handle.id
          ? 'focus'
          : info.hover === handle.id
            ? 'hover'
            : 'idle',
    );
    this.spec.drawOver?.(painter, model, info);
    painter.placeLabels();
    return painter;
  }

  private syncKeys(): void {
    this.keys.sync(
      this.handles.map((handle, i) => {
        const [x, y] = this.view.toScreen(handle.position);
        return {
          id: handle.id,
          name: this.names[i],
          x,
          y,
          depth: handle.position.length > 2,
        };
      }),
      this.view,
    );
  }

  private pick(at: Screen, pointerType: string): string | null {
    const reach = this.host.theme().sizes.handle + hitTolerance(pointerType);
    const nearest = nearestHandle(this.handles, this.view, at, reach);
    if (nearest !== null || !this.spec.pickAt) return nearest;
    return this.spec.pickAt(this.host.model(), this.view.toWorld(at), this.view.worldLength(reach));
  }

  private dragStart(id: string, at: Screen): void {
    if (id !== this.chosen) this.choose(null);
    this.host.hold();
    this.dragging = {
      drag: new HandleDrag(this.view, this.handles, id, at),
      key: `drag:${++dragSerial}`,
    };
    this.canvas.classList.add('dragging');
    this.redrawSoon();
  }

  private dragMove(at: Screen, shift: boolean): void {
    if (!this.dragging || !this.spec.moveHandle) return;
    const moved = this.dragging.drag.move(at, shift);
    if (!moved) return;
    this.host.set(this.spec.moveHandle(this.host.get(), moved.id, moved.to, this.host.model()), {
      coalesce: this.dragging.key,
    });
  }

  private dragEnd(): void {
    const id = this.dragging?.drag.id;
    this.dragging = null;
    this.host.settle();
    this.canvas.classList.remove('dragging');
    const handle = id ? this.handlesFor(this.host.model()).find((h) => h.id === id) : undefined;
    if (handle)
      this.host.announce(`${plainLabel(handle.label)} moved to ${fmtPoint(handle.position)}`);
    this.redrawSoon();
  }

  private hover(at: Screen | null): void {
    let id: string | null = null;
    let overHandle = false;
    if (at) {
      id = this.pick(at, 'mouse');
      overHandle = id !== null;
      if (id === null && this.spec.hoverAt) {
        id = this.spec.hoverAt(this.host.model(), this.view.toWorld(at), this.view.worldLength(8));
      }
    }
    this.canvas.classList.toggle('over-handle', overHandle);
    this.host.setHover(id);
  }

  private keyMove(id: string, delta: readonly number[], size: KeySize): void {
    const handle = this.handles.find((h) => h.id === id);
    if (!handle || !this.spec.moveHandle) return;
    const to = keyStep(this.view, handle.position, delta, size);
    this.host.set(this.spec.moveHandle(this.host.get(), id, to, this.host.model()), {
      coalesce: `key:${id}`,
      windowMs: 1000,
    });
    const moved = this.handlesFor(this.host.model()).find((h) => h.id === id);
    if (moved) this.host.announce(`${plainLabel(moved.label)} at ${fmtPoint(moved.position)}`);
  }

  /** Where handle `id` is now, in the figure's coordinates, or null. */
  handlePosition(id: string): Point | null {
    return this.handlesFor(this.host.model()).find((h) => h.id === id)?.position ?? null;
  }

  /** Shows the delete button of the handle a finger tapped (null hides it). */
  private choose(id: string | null): void {
    const handle = id === null ? undefined : this.handles.find((h) => h.id === id);
    const removable = handle !== undefined && this.spec.removeHandle !== undefined;
    this.chosen = removable ? handle.id : null;
    setHidden(this.deleteButton, !removable);
    if (removable) setText(this.deleteButton, `Delete ${plainLabel(handle.label)}`);
  }

  private add(at: Screen): void {
    if (!this.spec.addPoint) return;
    const next = this.spec.addPoint(this.host.get(), this.view.toWorld(at), this.host.model());
    if (next) {
      this.host.set(next, {});
      this.host.announce('Point added');
    } else this.host.announce('No more points can be added here');
  }

  private remove(id: string): void {
    if (!this.spec.removeHandle) return;
    const next = this.spec.removeHandle(this.host.get(), id, this.host.model());
    if (next) {
      this.host.set(next, {});
      this.host.announce('Point removed');
    } else this.host.announce('This point cannot be removed: the lesson needs it');
  }
}

/** An exercise's marks: the guess as a cross, the answer as a ring, a dashed line from one to the other. */
function drawMarks(painter: Painter, marks: readonly FigureMark[], theme: Theme): void {
  const guess = marks.find((m) => m.kind === 'guess');
  const answer = marks.find((m) => m.kind === 'answer');
  const size = painter.sizes.handle;
  if (guess && answer)
    painter.segment(guess.at, answer.at, {
      color: theme.accent,
      width: theme.sizes.line,
      dash: [6, 5],
    });
  if (answer)
    painter.ring(answer.at, size * 1.3, { color: theme.ink, width: theme.sizes.line * 1.4 });
  if (guess)
    painter.cross(guess.at, size * 1.2, { color: theme.accent, width: theme.sizes.line * 1.6 });
  for (const mark of marks) painter.labelClear(mark.label, mark.at, []);
}
