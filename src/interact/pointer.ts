/**
 * Pointer input on one canvas: mouse, touch and pen through pointer events.
 * It decides what a gesture means (drag a handle, pan, pinch-zoom, add a
 * point by double-click or long-press, remove by context action) and reports
 * it in screen pixels; it changes no state itself (mafs: drag logic apart
 * from the view).
 */
export type Screen = readonly [number, number];

export interface PointerCallbacks {
  /** The handle under `at`, if any, within a tolerance suited to the pointer type. */
  pick(at: Screen, pointerType: string): string | null;
  dragStart(id: string, at: Screen): void;
  /** `shift`: the Shift key is held (a figure in space then moves along one axis). */
  dragMove(id: string, at: Screen, shift: boolean): void;
  dragEnd(id: string): void;
  hover(at: Screen | null): void;
  /** Drag of empty space by a screen offset (pan, or orbit in space); absent for fixed figures. */
  pan?(dx: number, dy: number): void;
  zoom?(at: Screen, factor: number): void;
  add?(at: Screen): void;
  remove?(id: string): void;
  /** A press and release on empty space without moving (a tap or a click). */
  tap?(at: Screen): void;
  /** A handle pressed and released without moving it, with the pointer's type and where. */
  tapHandle?(id: string, pointerType: string, at: Screen): void;
}

/** Slack for a finger versus a mouse: a fingertip is about 9 mm wide. */
export function hitTolerance(pointerType: string): number {
  return pointerType === 'mouse' ? 10 : 22;
}

const LONG_PRESS_MS = 550;
const MOVE_SLOP = 8;

export function attachPointer(canvas: HTMLElement, cb: PointerCallbacks): () => void {
  const pointers = new Map<number, Screen>();
  let dragging: { id: string; pointer: number } | null = null;
  let pinchStart: { distance: number; mid: Screen } | null = null;
  let longPress: { timer: number; at: Screen; pointer: number } | null = null;
  /** Where the one pointer went down, on what, and whether it has moved since: a tap is neither dragged nor pinched. */
  let press: { at: Screen; pointer: number; id: string | null; moved: boolean } | null = null;

  const local = (e: PointerEvent | MouseEvent | WheelEvent): Screen => {
    const r = canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };

  const cancelLongPress = () => {
    if (longPress) window.clearTimeout(longPress.timer);
    longPress = null;
  };

  const onDown = (e: PointerEvent) => {
    if (e.button !== 0 && e.pointerType === 'mouse') return;
    const at = local(e);
    pointers.set(e.pointerId, at);
    try {
      canvas.setPointerCapture(e.pointerId);
    } catch {
      // The pointer is already gone (or was never a real one): drag without capture.
    }
    if (pointers.size === 2) {
      // A second finger: pinch instead of whatever the first one started.
      cancelLongPress();
      press = null;
      if (dragging) {
        cb.dragEnd(dragging.id);
        dragging = null;
      }
      const [a, b] = [...pointers.values()];
      pinchStart = {
        distance: Math.hypot(a[0] - b[0], a[1] - b[1]),
        mid: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2],
      };
      return;
    }
    const id = cb.pick(at, e.pointerType);
    press = pointers.size === 1 ? { at, pointer: e.pointerId, id, moved: false } : null;
    if (id !== null) {
      e.preventDefault();
      dragging = { id, pointer: e.pointerId };
      cb.dragStart(id, at);
      return;
    }
    if (e.pointerType !== 'mouse' && cb.add) {
      longPress = {
        at,
        pointer: e.pointerId,
        timer: window.setTimeout(() => {
          if (longPress) cb.add?.(longPress.at);
          longPress = null;
        }, LONG_PRESS_MS),
      };
    }
  };

  const onMove = (e: PointerEvent) => {
    const at = local(e);
    const previous = pointers.get(e.pointerId);
    if (!previous) {
      cb.hover(at);
      return;
    }
    pointers.set(e.pointerId, at);
    if (longPress && Math.hypot(at[0] - longPress.at[0], at[1] - longPress.at[1]) > MOVE_SLOP)
      cancelLongPress();
    if (press && Math.hypot(at[0] - press.at[0], at[1] - press.at[1]) > MOVE_SLOP)
      press.moved = true;
    if (dragging && dragging.pointer === e.pointerId) {
      cb.dragMove(dragging.id, at, e.shiftKey);
      return;
    }
    if (pointers.size === 2 && pinchStart && cb.zoom && cb.pan) {
      const [a, b] = [...pointers.values()];
      const distance = Math.hypot(a[0] - b[0], a[1] - b[1]);
      const mid: Screen = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
      cb.pan(mid[0] - pinchStart.mid[0], mid[1] - pinchStart.mid[1]);
      if (pinchStart.distance > 1) cb.zoom(mid, distance / pinchStart.distance);
      pinchStart = { distance, mid };
      return;
    }
    // One finger on empty space scrolls the page (the browser does it, as
    // touch-action allows); panning is two fingers, or a mouse or pen drag.
    if (pointers.size === 1 && cb.pan && e.pointerType !== 'touch')
      cb.pan(at[0] - previous[0], at[1] - previous[1]);
  };

  // The browser may scroll the page under one finger (touch-action: pan-x
  // pan-y) unless the touch starts on a handle, or is a second finger.
  const onTouchStart = (e: TouchEvent) => {
    if (e.touches.length > 1) {
      if (cb.zoom) e.preventDefault();
      return;
    }
    const touch = e.touches[0];
    const r = canvas.getBoundingClientRect();
    if (cb.pick([touch.clientX - r.left, touch.clientY - r.top], 'touch') !== null)
      e.preventDefault();
  };
  const onTouchMove = (e: TouchEvent) => {
    if (dragging || (e.touches.length > 1 && cb.zoom)) e.preventDefault();
  };

  const onUp = (e: PointerEvent) => {
    pointers.delete(e.pointerId);
    // Not moved, not taken over by the browser (a scroll cancels the pointer),
    // and on empty space not held long enough to add a point.
    let tap =
      press?.pointer === e.pointerId && !press.moved && e.type === 'pointerup' ? press : null;
    if (tap?.id === null && e.pointerType !== 'mouse' && cb.add && longPress === null) tap = null;
    press = null;
    if (longPress?.pointer === e.pointerId) cancelLongPress();
    if (dragging && dragging.pointer === e.pointerId) {
      cb.dragEnd(dragging.id);
      dragging = null;
    }
    if (pointers.size < 2) pinchStart = null;
    if (e.pointerType !== 'mouse') cb.hover(null);
    if (tap && tap.id === null) cb.tap?.(tap.at);
    else if (tap?.id) cb.tapHandle?.(tap.id, e.pointerType, tap.at);
  };

  const onLeave = () => {
    if (!dragging) cb.hover(null);
  };

  const onDoubleClick = (e: MouseEvent) => {
    const at = local(e);
    if (cb.add && cb.pick(at, 'mouse') === null) cb.add(at);
  };

  const onContextMenu = (e: MouseEvent) => {
    const id = cb.pick(local(e), 'mouse');
    if (id !== null && cb.remove) {
      e.preventDefault();
      cb.remove(id);
    }
  };

  const onWheel = (e: WheelEvent) => {
    if (!cb.zoom) return;
    e.preventDefault();
    cb.zoom(local(e), Math.exp(-e.deltaY * 0.0015));
  };

  // One list of listeners; aborting the signal removes them all.
  const listening = new AbortController();
  const options = { signal: listening.signal };
  canvas.addEventListener('pointerdown', onDown, options);
  canvas.addEventListener('pointermove', onMove, options);
  canvas.addEventListener('pointerup', onUp, options);
  canvas.addEventListener('pointercancel', onUp, options);
  canvas.addEventListener('pointerleave', onLeave, options);
  canvas.addEventListener('dblclick', onDoubleClick, options);
  canvas.addEventListener('contextmenu', onContextMenu, options);
  canvas.addEventListener('wheel', onWheel, { ...options, passive: false });
  canvas.addEventListener('touchstart', onTouchStart, { ...options, passive: false });
  canvas.addEventListener('touchmove', onTouchMove, { ...options, passive: false });
  return () => {
    cancelLongPress();
    listening.abort();
  };
}
