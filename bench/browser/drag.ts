// Dragging with real input, one mouse move per animation frame, traced: a
// movable point round a small circle, a slider's thumb to and fro.
//
// Pacing: move, then wait for the page's next requestAnimationFrame. Chromium
// answers a mouse move only once the page has dispatched it, so that frame is
// the one after the move's own: the move's frame has been drawn before the
// next move is sent, and each move gets a frame to itself (checked: the trace
// must show one dispatch per move). Waiting for a second frame as well adds an
// idle frame to every window (50 ms a move instead of 33 on a 60 Hz clock).
import type { Browser, Page } from '@playwright/test';
import { nextFrames } from './page';
import { mainThreadPerFrame } from './trace';

type Screen = readonly [number, number];

/** How long and how far a drag goes. */
export interface DragLimits {
  /** Frames to measure: one more move than this is made. */
  readonly frames: number;
  /** Wall-clock cap, so a slow page measures fewer frames instead of running for minutes. */
  readonly seconds: number;
}

/** The element whose state a drag changes, read after every frame to see that it did. */
export interface Watched {
  readonly selector: string;
  readonly index: number;
  /**
   * `value` of an input, `transform` of an element, or `handle`: where the
   * app says the point of that keyboard stand-in is (`splineLab.probe`), as a
   * stand-in waits for the drag's end before it moves.
   */
  readonly property: 'value' | 'transform' | 'handle';
}

export interface DragResult {
  /** Main-thread ms of each measured frame (task durations). */
  readonly perFrame: readonly number[];
  /** The same tasks' thread CPU ms. */
  readonly cpuPerFrame: readonly number[];
  readonly moves: number;
  /** Moves the page dispatched as its own event (fewer than `moves` if any were merged). */
  readonly dispatched: number;
  /** Moves after which the watched element had changed. */
  readonly changed: number;
  /** The page's own work per frame (its `spline-lab:frame` measures: derive + draw + panel), if it measures it. */
  readonly appPerFrame: readonly number[];
}

/** The name under which the app measures each frame's work. */
export const FRAME_MEASURE = 'spline-lab:frame';

const CATEGORIES = ['devtools.timeline', 'disabled-by-default-devtools.timeline'];
export const CIRCLE_RADIUS = 40;

/**
 * Presses at `path(0)`, then moves to `path(1)`, `path(2)`, … one move per
 * animation frame (move, then wait for the page's next frame) while a trace
 * records, and releases. Stops after `limits.frames + 1` moves or
 * `limits.seconds`, whichever comes first.
 */
export async function tracedDrag(
  browser: Browser,
  page: Page,
  path: (k: number) => Screen,
  watched: Watched,
  limits: DragLimits,
): Promise<DragResult> {
  const [x0, y0] = path(0);
  await page.mouse.move(x0, y0);
  await nextFrames(page);
  await page.mouse.down();
  await nextFrames(page);
  let last = await readAfterFrame(page, watched);
  let changed = 0;
  let moves = 0;
  await page.evaluate((name) => performance.clearMeasures(name), FRAME_MEASURE);
  await browser.startTracing(page, { categories: CATEGORIES });
  const deadline = performance.now() + limits.seconds * 1000;
  while (moves <= limits.frames && performance.now() < deadline) {
    moves++;
    const [x, y] = path(moves);
    await page.mouse.move(x, y);
    const now = await readAfterFrame(page, watched);
    if (now !== last) changed++;
    last = now;
  }
  const trace = await browser.stopTracing();
  const appPerFrame = await page.evaluate(
    (name) => performance.getEntriesByName(name).map((e) => e.duration),
    FRAME_MEASURE,
  );
  await page.mouse.up();
  await nextFrames(page);
  const { perFrame, cpuPerFrame, dispatchedMoves } = mainThreadPerFrame(trace.toString('utf8'));
  return { perFrame, cpuPerFrame, moves, dispatched: dispatchedMoves, changed, appPerFrame };
}

/** The page's hook for tools (src/app/main.ts): where handle `id` of a figure is. */
interface SplineLabProbe {
  probe(figure: string, point: null, id: string): { handle: readonly number[] | null } | null;
}

/** Waits for the next animation frame, then reads the watched element's state (no layout). */
function readAfterFrame(page: Page, watched: Watched): Promise<string> {
  return page.evaluate(
    ({ selector, index, property }) =>
      new Promise<string>((resolve) =>
        requestAnimationFrame(() => {
          const element = document.querySelectorAll<HTMLInputElement>(selector)[index];
          if (!element) resolve('');
          else if (property === 'value') resolve(element.value);
          else if (property === 'transform') resolve(element.style.transform);
          else {
            const figure = element.closest<HTMLElement>('.figure')?.dataset.figure ?? '';
            const lab = (window as unknown as { splineLab?: SplineLabProbe }).splineLab;
            const at = lab?.probe(figure, null, element.dataset.handle ?? '')?.handle;
            resolve(JSON.stringify(at ?? null));
          }
        }),
      ),
    watched,
  );
}

/**
 * A circle of CIRCLE_RADIUS through `start`, bending towards `inside` (the
 * canvas centre) so it stays on the figure; once round in `frames` moves.
 */
export function circlePath(start: Screen, inside: Screen, frames: number): (k: number) => Screen {
  const [dx, dy] = [inside[0] - start[0], inside[1] - start[1]];
  const length = Math.hypot(dx, dy) || 1;
  const [ux, uy] = [dx / length, dy / length];
  const centre: Screen = [start[0] + CIRCLE_RADIUS * ux, start[1] + CIRCLE_RADIUS * uy];
  return (k) => {
    const angle = (2 * Math.PI * k) / frames;
    // Start at -u from the centre and turn: (-u) rotated by `angle`.
    const [cos, sin] = [Math.cos(angle), Math.sin(angle)];
    return [
      centre[0] - CIRCLE_RADIUS * (ux * cos - uy * sin),
      centre[1] - CIRCLE_RADIUS * (ux * sin + uy * cos),
    ];
  };
}

/** What the page says about a range input, to place the pointer on its track. */
export interface SliderBox {
  readonly left: number;
  readonly width: number;
  readonly middleY: number;
  /** Where the thumb is, 0..1 of the range. */
  readonly fraction: number;
  /** One step as a fraction of the range (0 when the slider is continuous). */
  readonly stepFraction: number;
}

/** Chromium's default range thumb is about this wide; the track is this much shorter. */
const THUMB_PX = 16;
const SWEEP_LOW = 0.05;
const SWEEP_HIGH = 0.95;

/**
 * To and fro between 5% and 95% of the track at 1.25 steps a frame (0.5% of
 * the range if continuous), so the value changes on nearly every frame.
 */
export function sweepPath(slider: SliderBox): (k: number) => Screen {
  const speed = slider.stepFraction > 0 ? 1.25 * slider.stepFraction : 0.005;
  const span = SWEEP_HIGH - SWEEP_LOW;
  const start = Math.min(SWEEP_HIGH, Math.max(SWEEP_LOW, slider.fraction)) - SWEEP_LOW;
  return (k) => {
    const along = (start + k * speed) % (2 * span);
    const fraction = SWEEP_LOW + (along <= span ? along : 2 * span - along);
    return [slider.left + THUMB_PX / 2 + fraction * (slider.width - THUMB_PX), slider.middleY];
  };
}
