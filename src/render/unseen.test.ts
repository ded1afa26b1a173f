import { afterEach, describe, expect, it } from 'vitest';

/** A stand-in for the browser's IntersectionObserver: the test says what is in view. */
class FakeObserver {
  static last: FakeObserver | null = null;
  readonly targets: object[] = [];
  constructor(readonly report: (entries: { target: object; isIntersecting: boolean }[]) => void) {
    FakeObserver.last = this;
  }
  observe(target: object): void {
    this.targets.push(target);
  }
  see(target: object, inView: boolean): void {
    this.report([{ target, isIntersecting: inView }]);
  }
}

async function fresh() {
  (globalThis as { IntersectionObserver?: unknown }).IntersectionObserver = FakeObserver;
  const { vi } = await import('vitest');
  vi.resetModules();
  return import('./unseen');
}

afterEach(() => {
  delete (globalThis as { IntersectionObserver?: unknown }).IntersectionObserver;
});

/** A pointer event as the page sees it: a type, the buttons held, and where it was aimed. */
function pointer(type: string, buttons: number, on: EventTarget): Event {
  const event = new Event(type);
  Object.defineProperty(event, 'buttons', { value: buttons });
  Object.defineProperty(event, 'target', { value: on });
  return event;
}

describe('a drag begins on its first move', () => {
  it('is told once a drag, with what was pressed; a click and a hover are no drag', async () => {
    const { holdUnseenWhilePressed, onDragStart } = await fresh();
    const page = new EventTarget();
    const release = holdUnseenWhilePressed(page, () => {});
    const began: EventTarget[] = [];
    onDragStart((pressed) => began.push(pressed));
    const [button, handle] = [new EventTarget(), new EventTarget()];

    page.dispatchEvent(pointer('pointermove', 0, page));
    page.dispatchEvent(pointer('pointerdown', 1, button));
    page.dispatchEvent(pointer('pointerup', 0, button));
    expect(began).toEqual([]);

    page.dispatchEvent(pointer('pointerdown', 1, handle));
    page.dispatchEvent(pointer('pointermove', 1, page));
    page.dispatchEvent(pointer('pointermove', 1, page));
    expect(began).toEqual([handle]);
    page.dispatchEvent(pointer('pointerup', 0, handle));
    page.dispatchEvent(pointer('pointermove', 1, page));
    expect(began).toEqual([handle]);
    release();
  });
});

describe('what waits while a pointer is held', () => {
  it('writes in view at once, out of view on release or when it comes into view', async () => {
    const { holdUnseenWhilePressed, waitUnseen, watchSeen } = await fresh();
    const page = new EventTarget();
    let fits = 0;
    const release = holdUnseenWhilePressed(page, () => fits++);
    const caught: string[] = [];
    const [above, below, later] = [{}, {}, {}] as Element[];
    const owner = (name: string) => ({ catchUp: () => caught.push(name) });
    const [a, b, c] = [owner('above'), owner('below'), owner('later')];
    watchSeen(above, a);
    watchSeen(below, b);
    watchSeen(later, c);
    const observer = FakeObserver.last!;
    observer.see(above, true);
    observer.see(below, false);
    observer.see(later, false);

    // No pointer held: everything is written now, in view or not.
    expect([waitUnseen(above, a), waitUnseen(below, b)]).toEqual([false, false]);

    page.dispatchEvent(new Event('pointerdown'));
    expect(waitUnseen(above, a)).toBe(false);
    expect(waitUnseen(below, b)).toBe(true);
    expect(waitUnseen(later, c)).toBe(true);
    // Scrolled into view mid-drag: it catches up at once, and the page is told to fit it.
    observer.see(later, true);
    expect(caught).toEqual(['later']);
    expect(fits).toBe(1);
    expect(waitUnseen(later, c)).toBe(false);

    page.dispatchEvent(new Event('pointerup'));
    expect(caught).toEqual(['later', 'below']);
    expect(fits).toBe(2);
    // Nothing waits twice; a release still asks for a fit (boxes wait for it: liveBoxes.ts).
    page.dispatchEvent(new Event('pointerdown'));
    page.dispatchEvent(new Event('pointerup'));
    expect(caught).toEqual(['later', 'below']);
    expect(fits).toBe(3);
    release();
  });

  it('a move with no button down is a release heard late', async () => {
    const { holdUnseenWhilePressed, waitUnseen, watchSeen, pointerHeld } = await fresh();
    const page = new EventTarget();
    const release = holdUnseenWhilePressed(page, () => {});
    const hidden = {} as Element;
    let caught = 0;
    const owner = { catchUp: () => caught++ };
    watchSeen(hidden, owner);
    FakeObserver.last!.see(hidden, false);
    page.dispatchEvent(new Event('pointerdown'));
    expect(waitUnseen(hidden, owner)).toBe(true);
    const move = Object.assign(new Event('pointermove'), { buttons: 0 });
    page.dispatchEvent(move);
    expect(pointerHeld()).toBe(false);
    expect(caught).toBe(1);
    release();
  });

  it('without an IntersectionObserver everything counts as seen', async () => {
    const { vi } = await import('vitest');
    vi.resetModules();
    const { holdUnseenWhilePressed, waitUnseen, watchSeen } = await import('./unseen');
    const page = new EventTarget();
    const release = holdUnseenWhilePressed(page, () => {});
    const element = {} as Element;
    const owner = { catchUp: () => {} };
    watchSeen(element, owner);
    page.dispatchEvent(new Event('pointerdown'));
    expect(waitUnseen(element, owner)).toBe(false);
    release();
  });
});
