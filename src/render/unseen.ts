/**
 * What waits while a pointer is held (a point or a slider being dragged): a
 * panel's live numbers out of view, and the copies of formulas nobody reads
 * mid-drag. Every number written makes the browser lay out and paint its
 * formula or table again, on every drag frame: in hermite's panel five of
 * seven live formulas are below the fold, and writing them cost the main
 * thread more per frame than the figures (25 → 14 ms at 1920×1080, scale 2).
 * What waited is written the moment it comes into view or the pointer is let
 * go; a key press or Play writes everything at once, as before.
 */

/** Something a panel keeps up to date that can wait to be seen. */
export interface Unseen {
  /** Writes what waited (the newest values it was given). */
  catchUp(): void;
}

let pressed = false;
/** What has values waiting, and for which element it waits to be seen. */
const waiting = new Map<Unseen, Element>();
/** Work to do on release only (a formula's MathML copy). */
const onRelease = new Set<() => void>();
const outOfView = new WeakSet<Element>();
const owners = new WeakMap<Element, Unseen>();
/** Told when values that waited were written outside a frame: they are to be fitted. */
const caughtUpListeners = new Set<() => void>();

/** Within this margin of the screen a thing counts as in view (it is about to be). */
const VIEW_MARGIN = '64px';
let viewWatch: IntersectionObserver | null | undefined;

/** The one observer that says what is in view (none where there is none: all counts as seen). */
function viewWatcher(): IntersectionObserver | null {
  if (viewWatch !== undefined) return viewWatch;
  viewWatch =
    typeof IntersectionObserver === 'undefined'
      ? null
      : new IntersectionObserver(
          (entries) => {
            const arrived: Unseen[] = [];
            for (const entry of entries) {
              if (!entry.isIntersecting) {
                outOfView.add(entry.target);
                continue;
              }
              outOfView.delete(entry.target);
              const owner = owners.get(entry.target);
              if (owner && waiting.has(owner)) arrived.push(owner);
            }
            catchUp(arrived);
          },
          { rootMargin: VIEW_MARGIN },
        );
  return viewWatch;
}

function catchUp(arrived: readonly Unseen[], tell = true): void {
  if (arrived.length === 0) return;
  for (const owner of arrived) {
    waiting.delete(owner);
    owner.catchUp();
  }
  if (tell) for (const listener of caughtUpListeners) listener();
}

/** Watches `element` (what shows `owner`'s values) in and out of view. */
export function watchSeen(element: Element, owner: Unseen): void {
  owners.set(element, owner);
  viewWatcher()?.observe(element);
}

/**
 * Whether `owner` should wait instead of writing now (a pointer is held and
 * its element is out of view): if so it is noted, and catches up later.
 * Otherwise whatever it had waiting is forgotten, as it writes now.
 */
export function waitUnseen(element: Element, owner: Unseen): boolean {
  if (pressed && outOfView.has(element)) {
    waiting.set(owner, element);
    return true;
  }
  waiting.delete(owner);
  return false;
}

/** Whether a pointer is held anywhere on the page. */
export function pointerHeld(): boolean {
  return pressed;
}

/** Told each time a pointer is pressed on the page, before the press's own handlers. */
const pressListeners = new Set<() => void>();

/** Runs `job` each time a pointer is pressed on the page (before the page handles the press). */
export function onEveryPress(job: () => void): void {
  pressListeners.add(job);
}

/** Told on a press's first move with a button held: what was pressed, on its way to be dragged. */
const dragListeners = new Set<(pressed: EventTarget) => void>();
/** What the press being held began on, until its first move (then null). */
let pressTarget: EventTarget | null = null;

/**
 * Runs `job` on the first move of each drag, before the page handles the
 * move, with the element the press began on. A click, however it ends, is no
 * drag: a press let go before it moves never gets here.
 */
export function onDragStart(job: (pressed: EventTarget) => void): void {
  dragListeners.add(job);
}

/** Runs `job` once the pointer is let go (once, however often asked). */
export function whenReleased(job: () => void): void {
  onRelease.add(job);
}

function setPressed(on: boolean): void {
  if (!on) pressTarget = null;
  if (pressed === on) return;
  pressed = on;
  if (on) {
    for (const job of pressListeners) job();
    return;
  }
  catchUp([...waiting.keys()], false);
  const jobs = [...onRelease];
  onRelease.clear();
  for (const job of jobs) job();
  // What caught up is fitted in the next frame, and so are the live numbers'
  // boxes that waited for the release to be measured (liveBoxes.ts).
  for (const listener of caughtUpListeners) listener();
}

/**
 * Holds what is unseen while a pointer is pressed anywhere on `target` (the
 * page); `caughtUp` is told when values that waited are written (outside a
 * frame: fit them). Returns what undoes it (and writes what waited).
 */
export function holdUnseenWhilePressed(target: EventTarget, caughtUp: () => void): () => void {
  caughtUpListeners.add(caughtUp);
  const stop = new AbortController();
  const options = { capture: true, signal: stop.signal };
  target.addEventListener(
    'pointerdown',
    (e) => {
      setPressed(true);
      pressTarget = e.target;
    },
    options,
  );
  for (const type of ['pointerup', 'pointercancel'])
    target.addEventListener(type, () => setPressed(false), options);
  // The window losing focus ends a press; an element's blur, caught here on its
  // way down, does not: pressing a slider blurs the field focused before it,
  // and that ended every drag that began by moving the focus.
  target.addEventListener(
    'blur',
    (e) => {
      if (e.target === target) setPressed(false);
    },
    options,
  );
  // A release outside the window is never heard: the next move without buttons is.
  target.addEventListener(
    'pointermove',
    (e) => {
      if ((e as PointerEvent).buttons === 0) setPressed(false);
      else if (pressed && pressTarget) {
        const began = pressTarget;
        pressTarget = null;
        for (const job of dragListeners) job(began);
      }
    },
    options,
  );
  return () => {
    stop.abort();
    setPressed(false);
    caughtUpListeners.delete(caughtUp);
  };
}
