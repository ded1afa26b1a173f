/**
 * Keyboard access to movable points: one focusable element per handle, laid
 * over the canvas where the handle is drawn (so the browser scrolls to it and
 * screen readers can find it). Tab moves between points, the arrow keys move
 * the focused one (Shift: big steps, Alt: fine steps), Delete removes it.
 */
import type { KeySize } from './handleDrag';
import { setClass } from '../app/dom';

export interface KeyHandle {
  id: string;
  /** Accessible name, e.g. "P1 at (1.00, 2.00)". */
  name: string;
  /** Where it is drawn, in CSS pixels within the canvas. */
  x: number;
  y: number;
  /** A point in space: Ctrl (or ⌘) with ↑/↓ moves it along z. */
  depth?: boolean;
}

export interface HandleKeyCallbacks {
  /** Move by whole steps along each world axis ([dx, dy] or [dx, dy, dz]). */
  move(id: string, delta: readonly number[], size: KeySize): void;
  remove?(id: string): void;
  focus(id: string | null): void;
}

/** Arrow keys to a unit direction on screen axes turned to lesson axes (y up). */
export function arrowDirection(key: string): [number, number] | null {
  switch (key) {
    case 'ArrowLeft':
      return [-1, 0];
    case 'ArrowRight':
      return [1, 0];
    case 'ArrowUp':
      return [0, 1];
    case 'ArrowDown':
      return [0, -1];
    default:
      return null;
  }
}

export class HandleKeys {
  private readonly elements = new Map<string, HTMLElement>();
  /** What each element shows now, so unchanged handles cost no DOM write. */
  private readonly shown = new Map<
    string,
    { name: string; x: number; y: number; depth: boolean | null }
  >();
  /** The ids in the order last laid out. */
  private order: string[] = [];

  constructor(
    private readonly layer: HTMLElement,
    private readonly cb: HandleKeyCallbacks,
  ) {}

  /** Places one stand-in per handle; `size` is the figure's, in CSS pixels. */
  sync(handles: readonly KeyHandle[], size: { width: number; height: number }): void {
    let added = false;
    for (const handle of handles) {
      let el = this.elements.get(handle.id);
      if (!el) {
        el = this.create(handle.id);
        this.elements.set(handle.id, el);
        this.layer.appendChild(el);
        added = true;
      }
      let shown = this.shown.get(handle.id);
      if (!shown) {
        shown = { name: '', x: NaN, y: NaN, depth: null };
        this.shown.set(handle.id, shown);
      }
      if (shown.name !== handle.name) {
        shown.name = handle.name;
        el.setAttribute('aria-label', handle.name);
      }
      // A point far off the figure waits a figure's width beyond it (still
      // reachable by Tab), not millions of pixels away.
      const x = Math.max(-size.width, Math.min(handle.x, 2 * size.width));
      const y = Math.max(-size.height, Math.min(handle.y, 2 * size.height));
      if (shown.x !== x || shown.y !== y) {
        shown.x = x;
        shown.y = y;
        el.style.transform = `translate(${x}px, ${y}px)`;
      }
      const depth = handle.depth === true;
      if (shown.depth !== depth) {
        shown.depth = depth;
        el.setAttribute(
          'aria-description',
          depth
            ? 'Arrow keys move it in x and y, Ctrl with up and down in z'
            : 'Arrow keys move it',
        );
      }
    }
    // The list of points changed (one added or removed, or reordered): fix the DOM and the tab order.
    const same =
      !added &&
      handles.length === this.order.length &&
      handles.every((h, i) => h.id === this.order[i]);
    if (same) return;
    this.order = handles.map((h) => h.id);
    const seen = new Set(this.order);
    for (const [id, el] of this.elements) {
      if (!seen.has(id)) {
        el.remove();
        this.elements.delete(id);
        this.shown.delete(id);
      }
    }
    // Keep the tab order the lesson's order.
    let previous: Element | null = null;
    for (const handle of handles) {
      const el = this.elements.get(handle.id)!;
      const expected: Element | null = previous
        ? previous.nextElementSibling
        : this.layer.firstElementChild;
      if (expected !== el) this.layer.insertBefore(el, expected);
      previous = el;
    }
  }

  focus(id: string): void {
    this.elements.get(id)?.focus();
  }

  private create(id: string): HTMLElement {
    const el = document.createElement('div');
    setClass(el, 'handle-proxy');
    el.tabIndex = 0;
    el.setAttribute('role', 'button');
    el.setAttribute('aria-roledescription', 'movable point');
    el.dataset.handle = id;
    el.addEventListener('focus', () => this.cb.focus(id));
    el.addEventListener('blur', () => this.cb.focus(null));
    el.addEventListener('keydown', (e) => {
      const dir = arrowDirection(e.key);
      if (dir) {
        e.preventDefault();
        e.stopPropagation();
        const size = e.shiftKey ? 'big' : e.altKey ? 'fine' : 'normal';
        const alongZ = (e.ctrlKey || e.metaKey) && this.shown.get(id)?.depth && dir[1] !== 0;
        this.cb.move(id, alongZ ? [0, 0, dir[1]] : dir, size);
      } else if ((e.key === 'Delete' || e.key === 'Backspace') && this.cb.remove) {
        e.preventDefault();
        e.stopPropagation();
        this.cb.remove(id);
      }
    });
    return el;
  }
}
