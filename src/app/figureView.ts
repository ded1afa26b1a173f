import { HandleKeys, type KeySize } from '../interact/handleKeys';
import { attachPointer, hitTolerance, type Screen } from '../interact/pointer';
import type { Point } from '../math';
import { OrbitCamera } from '../render/orbitCamera';
import { Painter, splitSubscripts } from '../render/painter';
import { type Projection, niceStep } from '../render/projection';
import type { DrawingSurface } from '../render/surface';
import type { Theme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { fmtPoint } from './dom';
import type { DrawInfo, FigureSpec, Handle } from './lesson';

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
  /** A gesture ended: the state is final for now (write the link at once). */
  settle(): void;
}

/** Plain-text name of a lecture label: `P_{1,2}` → `P1,2`. */
export const plainLabel = (label: string) =>
  splitSubscripts(label)
    .map((r) => r.text)
    .join('');

/** How far (pixels) a stacked grab moves before its direction picks the handle. */
const PULL_SLOP = 4;
const AXES: Point[] = [
  [1, 0, 0],
  [0, 1, 0],
  [0, 0, 1],
];

interface Drag {
  id: string;
  /** Handles on the one spot grabbed, until the drag's direction picks one. */
  stack: string[] | null;
  start: Screen;
  /** Screen offset from the pointer to the handle's centre. */
  offset: [number, number];
  /** Where the handle was when grabbed (the drag plane passes through it). */
  anchor: Point;
  /** Along one world axis (space, Shift held), chosen by the first motion. */
  axis: Point | null;
  key: string;
}

let dragSerial = 0;

const hypot = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);

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
  private dragging: Drag | null = null;
  private focused: string | null = null;
  private fitted = false;
  /** The user moved the view: keep it (and put it in the link), unless asked to fit. */
  private userView = false;
  private size = { width: 0, height: 0 };
  /** The figure's box as last observed (CSS pixels), or null before the first observation. */
  private box: { width: number; height: number } | null = null;

  constructor(
    readonly spec: FigureSpec<S, M>,
    private readonly host: FigureHost<S, M>,
  ) {
    this.view = spec.kind === 'space' ? new OrbitCamera(spec.camera) : new Viewport();
    this.element = document.createElement('div');
    this.element.className = `figure figure-${spec.kind}`;
    this.element.dataset.figure = spec.id;
    this.element.style.flexGrow = String(spec.weight ?? 1);
    if (spec.height) {
      this.element.style.flex = `0 0 ${spec.height}px`;
      this.element.style.minHeight = `${spec.height}px`;
    }
    if (spec.aspect) this.element.style.aspectRatio = String(spec.aspect);
    this.canvas = document.createElement('canvas');
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', spec.title);
    this.canvas.dataset.figure = spec.id;
    const layer = document.createElement('div');
    layer.className = 'handle-layer';
    this.element.append(this.canvas, layer);
    this.keys = new HandleKeys(layer, {
      move: (id, delta, size) => this.keyMove(id, delta, size),
      remove: spec.removeHandle ? (id) => this.remove(id) : undefined,
      focus: (id) => {
        this.focused = id;
        host.invalidate(this);
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
    });
    this.resizeObserver = new ResizeObserver(([entry]) => {
      // The size is read here, once per change, never while drawing a frame.
      this.box = { width: entry.contentRect.width, height: entry.contentRect.height };
      host.invalidate(this);
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
    this.host.invalidate(this);
    this.host.viewChanged();
  }

  /** Fits the view to the lesson's bounds (key 0, a preset, first show). */
  fit(): void {
    const changed = this.userView;
    this.userView = false;
    this.fitted = false;
    this.host.invalidate(this);
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

  /** The view for the link, when the user has moved it; else null (the link fits). */
  viewText(): string | null {
    return this.movable && this.userView ? this.view.encode() : null;
  }

  /** Takes the view from a link; false if it could not be read (then it fits). */
  applyView(text: string | null): boolean {
    if (text === null || !this.movable) {
      if (this.userView) this.fit();
      return text === null;
    }
    // Fit first, so a camera read from the link has the distance that fits the scene.
    this.sizeCanvas();
    this.applyFit(this.host.model(), this.host.theme());
    const ok = this.view.decode(text);
    this.userView = ok;
    this.fitted = true;
    this.host.invalidate(this);
    return ok;
  }

  private applyFit(model: M, theme: Theme): void {
    const padding =
      this.spec.kind === 'plot'
        ? theme.sizes.small * 3.2
        : theme.sizes.handle * 2 + theme.sizes.label * 1.6;
    this.view.fit(this.spec.bounds(model), padding, this.spec.kind !== 'plot');
    this.fitted = true;
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

  /** Draws the model to the canvas. */
  draw(model: M): void {
    if (this.sizeCanvas() && !this.userView) this.fitted = false;
    const theme = this.host.theme();
    const alwaysFit = this.spec.kind === 'plot' || this.spec.kind === 'drawing';
    if (!this.fitted || alwaysFit) this.applyFit(model, theme);
    const ctx = this.canvas.getContext('2d');
    if (!ctx) return;
    const dpr = window.devicePixelRatio || 1;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    this.render(ctx, model, theme, this.host.info());
    this.syncKeys();
  }

  private handlesFor(model: M): Handle[] {
    if (this.handlesOf !== model) {
      this.handles = this.spec.handles?.(model) ?? [];
      this.handlesOf = model;
    }
    return this.handles;
  }

  /** Draws the figure to any surface at the current view: the canvas, an SVG export, a test recording. */
  render(surface: DrawingSurface, model: M, theme: Theme, info: DrawInfo): Painter {
    const painter = new Painter(surface, this.view, theme);
    painter.clear();
    if (this.spec.kind === 'geometry' && !info.thumbnail) painter.grid();
    this.spec.draw(painter, model, info);
    const handles = this.handlesFor(model);
    if (info.thumbnail) return painter;
    for (const handle of handles) {
      const state =
        this.dragging?.id === handle.id
          ? 'drag'
          : this.focused === handle.id
            ? 'focus'
            : info.hover === handle.id
              ? 'hover'
              : 'idle';
      painter.handle(handle.position, {
        color: handle.color,
        shape: handle.shape,
        state,
        // A small handle grows to full size while it is held, hovered or focused.
        radius: handle.small && state === 'idle' ? theme.sizes.handle * 0.5 : undefined,
      });
      if (handle.showLabel !== false) {
        painter.label(handle.label, handle.position, {
          dx: theme.sizes.handle + 4,
          dy: -(theme.sizes.handle + theme.sizes.label * 0.45),
          color: handle.color ?? theme.ink,
          halo: true,
          bold: true,
        });
      }
    }
    this.spec.drawOver?.(painter, model, info);
    return painter;
  }

  private syncKeys(): void {
    this.keys.sync(
      this.handles.map((handle) => {
        const [x, y] = this.view.toScreen(handle.position);
        return {
          id: handle.id,
          name: `${plainLabel(handle.label)} at ${fmtPoint(handle.position)}`,
          x,
          y,
          depth: handle.position.length > 2,
        };
      }),
      this.view,
    );
  }

  /** Handles within reach of `at`, nearest first (later handles win ties: they are drawn on top). */
  private within(at: Screen, reach: number): { id: string; d: number; screen: Screen }[] {
    const found: { id: string; d: number; screen: Screen }[] = [];
    this.handles.forEach((handle, order) => {
      const screen = this.view.toScreen(handle.position);
      const d = hypot(screen, at);
      if (d <= reach) found.push({ id: handle.id, d: d - order * 1e-9, screen });
    });
    return found.sort((a, b) => a.d - b.d);
  }

  private pick(at: Screen, pointerType: string): string | null {
    const reach = this.host.theme().sizes.handle + hitTolerance(pointerType);
    const nearest = this.within(at, reach)[0];
    if (nearest) return nearest.id;
    if (this.spec.pickAt) {
      return this.spec.pickAt(
        this.host.model(),
        this.view.toWorld(at),
        this.view.worldLength(reach),
      );
    }
    return null;
  }

  private handleById(id: string): Handle | undefined {
    return this.handles.find((h) => h.id === id);
  }

  private dragStart(id: string, at: Screen): void {
    const handle = this.handleById(id);
    if (!handle) {
      // Grabbed by pickAt (e.g. a cursor line): no handle to stack with.
      this.dragging = {
        id,
        stack: null,
        start: at,
        offset: [0, 0],
        anchor: this.view.toWorld(at),
        axis: null,
        key: `drag:${++dragSerial}`,
      };
      return;
    }
    const screen = this.view.toScreen(handle.position);
    // Every handle on the same spot as the one grabbed: the drag's direction will pick.
    const stack = this.handles
      .filter((h) => hypot(this.view.toScreen(h.position), screen) < 1)
      .map((h) => h.id);
    this.dragging = {
      id,
      stack: stack.length > 1 ? stack : null,
      start: at,
      offset: [screen[0] - at[0], screen[1] - at[1]],
      anchor: handle.position,
      axis: null,
      key: `drag:${++dragSerial}`,
    };
    this.canvas.classList.add('dragging');
    this.host.invalidate(this);
  }

  /** Of handles stacked on one spot, the one this pull direction (screen) means. */
  private choose(stack: string[], motion: [number, number]): string {
    const pulls = stack.map((id) => this.handleById(id)?.pull);
    if (pulls.some(Boolean)) {
      let best = stack[0];
      let bestScore = -Infinity;
      stack.forEach((id, i) => {
        const pull = pulls[i];
        if (!pull) return;
        const anchor = this.handleById(id)!.position;
        const a = this.view.toScreen(anchor);
        const b = this.view.toScreen(
          anchor.map((v, k) => v + (pull[k] ?? 0) * this.view.worldLength(40, anchor)),
        );
        const length = hypot(a, b) || 1;
        const score = ((b[0] - a[0]) * motion[0] + (b[1] - a[1]) * motion[1]) / length;
        if (score > bestScore) {
          bestScore = score;
          best = id;
        }
      });
      return best;
    }
    // Right or up (screen y down) picks the last of the stack, left or down the first.
    return motion[0] - motion[1] >= 0 ? stack[stack.length - 1] : stack[0];
  }

  private dragMove(at: Screen, shift: boolean): void {
    const drag = this.dragging;
    if (!drag || !this.spec.moveHandle) return;
    const motion: [number, number] = [at[0] - drag.start[0], at[1] - drag.start[1]];
    if (drag.stack) {
      if (Math.hypot(motion[0], motion[1]) < PULL_SLOP) return;
      drag.id = this.choose(drag.stack, motion);
      drag.stack = null;
    }
    const screen: Screen = [at[0] + drag.offset[0], at[1] + drag.offset[1]];
    let to: Point;
    if (this.view instanceof OrbitCamera) {
      if (shift && !drag.axis && Math.hypot(motion[0], motion[1]) >= PULL_SLOP) {
        // Along the world axis whose screen direction is closest to the motion.
        const camera = this.view;
        const scores = AXES.map((axis) => {
          const [dx, dy] = camera.screenDirection(drag.anchor, axis);
          return Math.abs(dx * motion[0] + dy * motion[1]);
        });
        drag.axis = AXES[scores.indexOf(Math.max(...scores))];
      }
      if (!shift) drag.axis = null;
      to = drag.axis
        ? this.view.closestOnAxis(screen, drag.anchor, [...drag.axis])
        : this.view.toWorld(screen, drag.anchor);
    } else to = this.view.toWorld(screen);
    this.host.set(this.spec.moveHandle(this.host.get(), drag.id, to, this.host.model()), {
      coalesce: drag.key,
    });
  }

  private dragEnd(): void {
    const id = this.dragging?.id;
    this.dragging = null;
    this.host.settle();
    this.canvas.classList.remove('dragging');
    const handle = id ? this.handlesFor(this.host.model()).find((h) => h.id === id) : undefined;
    if (handle)
      this.host.announce(`${plainLabel(handle.label)} moved to ${fmtPoint(handle.position)}`);
    this.host.invalidate(this);
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
    const handle = this.handleById(id);
    if (!handle || !this.spec.moveHandle) return;
    // About 8 pixels a press, on each axis's own scale (a plot's axes differ).
    const factor = size === 'big' ? 10 : size === 'fine' ? 0.1 : 1;
    const p = handle.position;
    const origin = this.view.toScreen(p);
    const stepFor = (axis: number) => {
      if (this.view.dimension === 3) return niceStep(this.view.worldLength(8, p)) * factor;
      const unit = p.map((_, k) => (k === axis ? p[k] + 1 : p[k]));
      const pixels = hypot(this.view.toScreen(unit), origin);
      return niceStep(8 / pixels) * factor;
    };
    const snap = (v: number, step: number) => Number((Math.round(v / step) * step).toPrecision(12));
    // Only the axis that moves lands on the step grid; the others stay exact.
    const to = p.map((v, k) => (delta[k] ? snap(v + delta[k] * stepFor(k), stepFor(k)) : v));
    this.host.set(this.spec.moveHandle(this.host.get(), id, to, this.host.model()), {
      coalesce: `key:${id}`,
      windowMs: 1000,
    });
    const moved = this.handlesFor(this.host.model()).find((h) => h.id === id);
    if (moved) this.host.announce(`${plainLabel(moved.label)} at ${fmtPoint(moved.position)}`);
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
