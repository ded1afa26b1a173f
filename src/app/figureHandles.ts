/**
 * A figure's handles as the user works them: which one a pointer picks or
 * hovers, a drag from its start to its end, the arrow keys on the focused one,
 * adding and removing points, and the delete button a finger's tap offers.
 * The handles are the model's last drawn, computed once per model; a change is
 * handed to the host as a new state (interaction only ever changes state).
 */
import { HandleDrag, type KeySize, keyStep, nearestHandle } from '../interact/handleDrag';
import { HandleKeys } from '../interact/handleKeys';
import { hitTolerance, type Screen } from '../interact/pointer';
import { drawHandles, plainLabel } from '../render/handles';
import type { Painter } from '../render/painter';
import type { Projection } from '../render/projection';
import { fmtPoint, setClass, setHidden, setText } from './dom';
import type { FigureHost } from './figureView';
import type { FigureSpec, Handle, Point } from './lesson';
import { SpokenNames } from './spokenNames';

let dragSerial = 0;

/** What the handles need of the page: the state to change, and where to say what happened. */
export type HandleHost<S, M> = Pick<
  FigureHost<S, M>,
  'get' | 'model' | 'set' | 'theme' | 'setHover' | 'announce' | 'hold' | 'settle' | 'tap'
>;

/** The handles of one figure: picking, dragging, keys, adding, removing and the delete button. */
export class FigureHandles<S, M> {
  /** The handles of the model last drawn, computed once per model. */
  private handles: Handle[] = [];
  private handlesOf: M | null = null;
  private names: string[] = [];
  private readonly spokenNames = new SpokenNames();
  private readonly keys: HandleKeys;
  private dragging: { drag: HandleDrag; key: string } | null = null;
  /** The handle a finger tapped: its delete button is shown. */
  private chosen: string | null = null;
  /** A finger has no right-click or Delete key: a tapped point offers its own delete button. */
  readonly deleteButton: HTMLButtonElement;
  private focused: string | null = null;

  constructor(
    private readonly spec: FigureSpec<S, M>,
    private readonly host: HandleHost<S, M>,
    private readonly view: Projection,
    private readonly canvas: HTMLCanvasElement,
    /** The layer over the canvas that holds the handles' focusable stand-ins. */
    layer: HTMLElement,
    /** The figure must be drawn again (a drag began or ended, a handle took focus). */
    private readonly redraw: () => void,
  ) {
    this.keys = new HandleKeys(layer, {
      move: (id, delta, size) => this.keyMove(id, delta, size),
      remove: spec.removeHandle ? (id) => this.remove(id) : undefined,
      focus: (id) => {
        this.focused = id;
        this.redraw();
      },
    });
    this.deleteButton = document.createElement('button');
    this.deleteButton.type = 'button';
    setClass(this.deleteButton, 'delete-point');
    setHidden(this.deleteButton, true);
    this.deleteButton.addEventListener('click', () => {
      if (this.chosen) this.remove(this.chosen);
      this.choose(null);
    });
  }

  /** The handles of `model`, computed once per model (with their spoken names). */
  of(model: M): Handle[] {
    if (this.handlesOf !== model) {
      this.handles = this.spec.handles?.(model) ?? [];
      this.handlesOf = model;
      this.names = this.spokenNames.of(this.handles);
    }
    return this.handles;
  }

  /** Draws `handles`, each as held, focused, hovered (`hover`) or idle. */
  draw(painter: Painter, handles: readonly Handle[], hover: string | null): void {
    drawHandles(painter, handles, (handle) =>
      this.dragging?.drag.id === handle.id
        ? 'drag'
        : this.focused === handle.id
          ? 'focus'
          : hover === handle.id
            ? 'hover'
            : 'idle',
    );
  }

  /**
   * Puts the keyboard's stand-ins where the handles last drawn are on screen
   * now. While a pointer holds a handle they wait for the drag's end (which
   * draws again): the pointer is what the user works then, and moving a
   * stand-in on every frame had Chromium rebuild its compositing layers for
   * the page's every stand-in (road, 500 villages: 0.8 ms of a 16 ms frame).
   */
  syncKeys(): void {
    if (this.dragging) return;
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

  /** Where handle `id` is now, in the figure's coordinates, or null. */
  position(id: string): Point | null {
    return this.of(this.host.model()).find((h) => h.id === id)?.position ?? null;
  }

  /** The handle under `at`, within a reach suited to the pointer, or what the figure picks there. */
  pick(at: Screen, pointerType: string): string | null {
    const reach = this.host.theme().sizes.handle + hitTolerance(pointerType);
    const nearest = nearestHandle(this.handles, this.view, at, reach);
    if (nearest !== null || !this.spec.pickAt) return nearest;
    return this.spec.pickAt(this.host.model(), this.view.toWorld(at), this.view.worldLength(reach));
  }

  /** A drag of handle `id` begins: one undo step, and the link waits for its end. */
  dragStart(id: string, at: Screen): void {
    if (id !== this.chosen) this.choose(null);
    this.host.hold();
    this.dragging = {
      drag: new HandleDrag(this.view, this.handles, id, at),
      key: `drag:${++dragSerial}`,
    };
    this.canvas.classList.add('dragging');
    this.redraw();
  }

  /** The handle follows the pointer (Shift: a point in space along one axis). */
  dragMove(at: Screen, shift: boolean): void {
    if (!this.dragging || !this.spec.moveHandle) return;
    const moved = this.dragging.drag.move(at, shift);
    if (!moved) return;
    this.host.set(this.spec.moveHandle(this.host.get(), moved.id, moved.to, this.host.model()), {
      coalesce: this.dragging.key,
    });
  }

  /** The drag ends: where the handle went is said aloud. */
  dragEnd(): void {
    const id = this.dragging?.drag.id;
    this.dragging = null;
    this.host.settle();
    this.canvas.classList.remove('dragging');
    const handle = id ? this.of(this.host.model()).find((h) => h.id === id) : undefined;
    if (handle)
      this.host.announce(`${plainLabel(handle.label)} moved to ${fmtPoint(handle.position)}`);
    this.redraw();
  }

  /** What the pointer is over now (a handle, or what the figure names there), or null. */
  hover(at: Screen | null): void {
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

  /** A tap on empty space: the delete button goes, and the tap may be a guess. */
  tap(at: Screen): void {
    this.choose(null);
    if (this.spec.kind !== 'space') this.host.tap(this.spec.id, this.view.toWorld(at));
  }

  /** A tap on a handle: a finger's shows its delete button, unless the tap was a guess. */
  tapHandle(id: string, pointerType: string, at: Screen): void {
    // A guess may be right next to a point: the tap is the guess, if one is asked for.
    const guessed =
      this.spec.kind !== 'space' && this.host.tap(this.spec.id, this.view.toWorld(at));
    this.choose(guessed || pointerType === 'mouse' ? null : id);
  }

  private keyMove(id: string, delta: readonly number[], size: KeySize): void {
    const handle = this.handles.find((h) => h.id === id);
    if (!handle || !this.spec.moveHandle) return;
    const to = keyStep(this.view, handle.position, delta, size);
    this.host.set(this.spec.moveHandle(this.host.get(), id, to, this.host.model()), {
      coalesce: `key:${id}`,
      windowMs: 1000,
    });
    const moved = this.of(this.host.model()).find((h) => h.id === id);
    if (moved) this.host.announce(`${plainLabel(moved.label)} at ${fmtPoint(moved.position)}`);
  }

  /** Shows the delete button of the handle a finger tapped (null hides it). */
  private choose(id: string | null): void {
    const handle = id === null ? undefined : this.handles.find((h) => h.id === id);
    const removable = handle !== undefined && this.spec.removeHandle !== undefined;
    this.chosen = removable ? handle.id : null;
    setHidden(this.deleteButton, !removable);
    if (removable) setText(this.deleteButton, `Delete ${plainLabel(handle.label)}`);
  }

  /** Adds a point at `at` (double-click, long-press), if the lesson allows one there. */
  add(at: Screen): void {
    if (!this.spec.addPoint) return;
    const next = this.spec.addPoint(this.host.get(), this.view.toWorld(at), this.host.model());
    if (next) {
      this.host.set(next, {});
      this.host.announce('Point added');
    } else this.host.announce('No more points can be added here');
  }

  /** Removes handle `id` (Delete, context action, the delete button), if the lesson can spare it. */
  remove(id: string): void {
    if (!this.spec.removeHandle) return;
    const next = this.spec.removeHandle(this.host.get(), id, this.host.model());
    if (next) {
      this.host.set(next, {});
      this.host.announce('Point removed');
    } else this.host.announce('This point cannot be removed: the lesson needs it');
  }
}
