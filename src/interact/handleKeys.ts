/**
 * Keyboard access to movable points: one focusable element per handle, laid
 * over the canvas where the handle is drawn (so the browser scrolls to it and
 * screen readers can find it). Tab moves between points, the arrow keys move
 * the focused one (Shift: big steps, Alt: fine steps), Delete removes it.
 */
export interface KeyHandle {
  id: string;
  /** Accessible name, e.g. "P1 at (1.00, 2.00)". */
  name: string;
  /** Where it is drawn, in CSS pixels within the canvas. */
  x: number;
  y: number;
}

export interface HandleKeyCallbacks {
  move(id: string, dx: number, dy: number, size: 'normal' | 'big' | 'fine'): void;
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

  constructor(
    private readonly layer: HTMLElement,
    private readonly cb: HandleKeyCallbacks,
  ) {}

  sync(handles: readonly KeyHandle[]): void {
    const seen = new Set<string>();
    for (const handle of handles) {
      seen.add(handle.id);
      let el = this.elements.get(handle.id);
      if (!el) {
        el = this.create(handle.id);
        this.elements.set(handle.id, el);
        this.layer.appendChild(el);
      }
      if (el.getAttribute('aria-label') !== handle.name) el.setAttribute('aria-label', handle.name);
      el.style.transform = `translate(${handle.x}px, ${handle.y}px)`;
    }
    for (const [id, el] of this.elements) {
      if (!seen.has(id)) {
        el.remove();
        this.elements.delete(id);
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
    el.className = 'handle-proxy';
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
        this.cb.move(id, dir[0], dir[1], e.shiftKey ? 'big' : e.altKey ? 'fine' : 'normal');
      } else if ((e.key === 'Delete' || e.key === 'Backspace') && this.cb.remove) {
        e.preventDefault();
        e.stopPropagation();
        this.cb.remove(id);
      }
    });
    return el;
  }
}
