import { HandleKeys } from '../interact/handleKeys';
import { attachPointer, hitTolerance, type Screen } from '../interact/pointer';
import { Painter, splitSubscripts } from '../render/painter';
import type { DrawingSurface } from '../render/surface';
import type { Theme } from '../render/theme';
import { Viewport, niceStep } from '../render/viewport';
import { fmtPoint } from './dom';
import type { DrawInfo, FigureSpec, Handle, Point2 } from './lesson';

export interface FigureHost<S> {
  get(): S;
  set(next: S, options: { coalesce?: string; windowMs?: number; record?: boolean }): void;
  theme(): Theme;
  info(): DrawInfo;
  setHover(id: string | null): void;
  announce(text: string): void;
  requestDraw(): void;
  /** A gesture ended: the state is final for now (write the link at once). */
  settle(): void;
}

/** Plain-text name of a lecture label: `P_{1,2}` → `P1,2`. */
export const plainLabel = (label: string) =>
  splitSubscripts(label)
    .map((r) => r.text)
    .join('');

let dragSerial = 0;

/** One canvas of a lesson, sharp at any devicePixelRatio, with its handles. */
export class FigureView<S> {
  readonly element: HTMLElement;
  readonly canvas: HTMLCanvasElement;
  readonly view = new Viewport();
  private readonly keys: HandleKeys;
  private readonly detach: () => void;
  private readonly resizeObserver: ResizeObserver;
  private handles: Handle[] = [];
  private dragging: { id: string; offset: [number, number]; key: string } | null = null;
  private focused: string | null = null;
  private fitted = false;
  /** The user moved the view: keep it, unless asked to fit. */
  private userView = false;

  constructor(
    readonly spec: FigureSpec<S>,
    private readonly host: FigureHost<S>,
  ) {
    this.element = document.createElement('div');
    this.element.className = `figure figure-${spec.kind}`;
    this.element.style.flexGrow = String(spec.weight ?? 1);
    this.canvas = document.createElement('canvas');
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', spec.title);
    this.canvas.dataset.figure = spec.id;
    const layer = document.createElement('div');
    layer.className = 'handle-layer';
    this.element.append(this.canvas, layer);
    this.keys = new HandleKeys(layer, {
      move: (id, dx, dy, size) => this.keyMove(id, dx, dy, size),
      remove: spec.removeHandle ? (id) => this.remove(id) : undefined,
      focus: (id) => {
        this.focused = id;
        host.requestDraw();
      },
    });
    const geometry = spec.kind === 'geometry';
    this.detach = attachPointer(this.canvas, {
      pick: (at, type) => this.pick(at, type),
      dragStart: (id, at) => this.dragStart(id, at),
      dragMove: (id, at) => this.dragMove(id, at),
      dragEnd: () => this.dragEnd(),
      hover: (at) => this.hover(at),
      pan: geometry
        ? (dx, dy) => {
            this.userView = true;
            this.view.panBy(dx, dy);
            host.requestDraw();
          }
        : undefined,
      zoom: geometry ? (at, factor) => this.zoom(at, factor) : undefined,
      add: spec.addPoint ? (at) => this.add(at) : undefined,
      remove: spec.removeHandle ? (id) => this.remove(id) : undefined,
    });
    this.resizeObserver = new ResizeObserver(() => host.requestDraw());
    this.resizeObserver.observe(this.element);
  }

  destroy(): void {
    this.detach();
    this.resizeObserver.disconnect();
  }

  /** Fits the view to the lesson's bounds (key 0, a preset, first show). */
  fit(): void {
    this.userView = false;
    this.fitted = false;
    this.host.requestDraw();
  }

  zoom(at: Screen | null, factor: number): void {
    if (this.spec.kind !== 'geometry') return;
    this.userView = true;
    this.view.zoomAt(at ?? [this.view.width / 2, this.view.height / 2], factor);
    this.host.requestDraw();
  }

  private applyFit(state: S, theme: Theme): void {
    const padding =
      this.spec.kind === 'plot'
        ? theme.sizes.small * 3.2
        : theme.sizes.handle * 2 + theme.sizes.label * 1.6;
    this.view.fit(this.spec.bounds(state), padding, this.spec.kind === 'geometry');
    this.fitted = true;
  }

  /** Draws to the canvas; sizes it to its box first. */
  draw(state: S): void {
    const rect = this.element.getBoundingClientRect();
    const width = Math.max(1, Math.round(rect.width));
    const height = Math.max(1, Math.round(rect.height));
    const dpr = window.devicePixelRatio || 1;
    if (
      this.canvas.width !== Math.round(width * dpr) ||
      this.canvas.height !== Math.round(height * dpr)
    ) {
      this.canvas.width = Math.round(width * dpr);
      this.canvas.height = Math.round(height * dpr);
      this.canvas.style.width = `${width}px`;
      this.canvas.style.height = `${height}px`;
      if (!this.userView) this.fitted = false;
    }
    this.view.resize(width, height);
    const theme = this.host.theme();
    if (!this.fitted || this.spec.kind === 'plot') this.applyFit(state, theme);
    const ctx = this.canvas.getContext('2d');
    if (!ctx) return;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    this.render(ctx, state, theme, this.host.info());
    this.syncKeys();
  }

  /** Draws the figure to any surface at the current view: the canvas, an SVG export. */
  render(surface: DrawingSurface, state: S, theme: Theme, info: DrawInfo): void {
    const painter = new Painter(surface, this.view, theme);
    painter.clear();
    if (this.spec.kind === 'geometry' && !info.thumbnail) painter.grid();
    this.spec.draw(painter, state, info);
    this.handles = this.spec.handles?.(state) ?? [];
    if (info.thumbnail) return;
    for (const handle of this.handles) {
      const stateName =
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
        state: stateName,
        // A small handle grows to full size while it is held, hovered or focused.
        radius: handle.small && stateName === 'idle' ? theme.sizes.handle * 0.5 : undefined,
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
    this.spec.drawOver?.(painter, state, info);
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
        };
      }),
    );
  }

  private pick(at: Screen, pointerType: string): string | null {
    const theme = this.host.theme();
    const reach = theme.sizes.handle + hitTolerance(pointerType);
    let best: string | null = null;
    let bestDistance = reach;
    // Later handles are drawn on top, so they win ties.
    for (const handle of this.handles) {
      const [x, y] = this.view.toScreen(handle.position);
      const d = Math.hypot(x - at[0], y - at[1]);
      if (d <= bestDistance) {
        best = handle.id;
        bestDistance = d;
      }
    }
    if (best === null && this.spec.pickAt) {
      best = this.spec.pickAt(this.host.get(), this.view.toWorld(at), this.view.worldLength(reach));
    }
    return best;
  }

  private handleById(id: string): Handle | undefined {
    return this.handles.find((h) => h.id === id);
  }

  private dragStart(id: string, at: Screen): void {
    const handle = this.handleById(id);
    if (!handle) return;
    const world = this.view.toWorld(at);
    this.dragging = {
      id,
      offset: [handle.position[0] - world[0], handle.position[1] - world[1]],
      key: `drag:${++dragSerial}`,
    };
    this.canvas.classList.add('dragging');
    this.host.requestDraw();
  }

  private dragMove(id: string, at: Screen): void {
    if (!this.dragging || !this.spec.moveHandle) return;
    const world = this.view.toWorld(at);
    const to: Point2 = [world[0] + this.dragging.offset[0], world[1] + this.dragging.offset[1]];
    this.host.set(this.spec.moveHandle(this.host.get(), id, to), { coalesce: this.dragging.key });
  }

  private dragEnd(): void {
    const id = this.dragging?.id;
    this.dragging = null;
    this.host.settle();
    this.canvas.classList.remove('dragging');
    const handle = id ? this.handleById(id) : undefined;
    if (handle)
      this.host.announce(`${plainLabel(handle.label)} moved to ${fmtPoint(handle.position)}`);
    this.host.requestDraw();
  }

  private hover(at: Screen | null): void {
    let id: string | null = null;
    if (at) {
      id = this.pick(at, 'mouse');
      if (id === null && this.spec.hoverAt) {
        id = this.spec.hoverAt(this.host.get(), this.view.toWorld(at), this.view.worldLength(8));
      }
    }
    this.canvas.classList.toggle('over-handle', at !== null && this.pick(at, 'mouse') !== null);
    this.host.setHover(id);
  }

  private keyMove(id: string, dx: number, dy: number, size: 'normal' | 'big' | 'fine'): void {
    const handle = this.handleById(id);
    if (!handle || !this.spec.moveHandle) return;
    // About 8 pixels a press, on each axis's own scale (a plot's axes differ).
    const factor = size === 'big' ? 10 : size === 'fine' ? 0.1 : 1;
    const stepX = niceStep(8 / this.view.scaleX) * factor;
    const stepY = niceStep(8 / this.view.scaleY) * factor;
    const snap = (v: number, step: number) => Number((Math.round(v / step) * step).toPrecision(12));
    // Only the axis that moves lands on the step grid; the other stays exact.
    const [x, y] = handle.position;
    const to: Point2 = [
      dx === 0 ? x : snap(x + dx * stepX, stepX),
      dy === 0 ? y : snap(y + dy * stepY, stepY),
    ];
    this.host.set(this.spec.moveHandle(this.host.get(), id, to), {
      coalesce: `key:${id}`,
      windowMs: 1000,
    });
    const moved = this.spec.handles?.(this.host.get()).find((h) => h.id === id);
    if (moved) this.host.announce(`${plainLabel(moved.label)} at ${fmtPoint(moved.position)}`);
  }

  private add(at: Screen): void {
    if (!this.spec.addPoint) return;
    const next = this.spec.addPoint(this.host.get(), this.view.toWorld(at));
    if (next) {
      this.host.set(next, {});
      this.host.announce('Point added');
    } else this.host.announce('No more points can be added here');
  }

  private remove(id: string): void {
    if (!this.spec.removeHandle) return;
    const next = this.spec.removeHandle(this.host.get(), id);
    if (next) {
      this.host.set(next, {});
      this.host.announce('Point removed');
    } else this.host.announce('This point cannot be removed: the lesson needs it');
  }
}
