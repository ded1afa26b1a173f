// What every benchmark page shares: the browser, the screen it runs at, and a
// watcher that notes when the first figure is on screen.
import { chromium, type Browser, type BrowserContext, type Page } from '@playwright/test';
import { chromiumArgs } from '../../tests/chromium';

/** 1920×1080 CSS pixels at device scale 2: every canvas has 4× the pixels of scale 1. */
const SCREEN = { viewport: { width: 1920, height: 1080 }, deviceScaleFactor: 2 };

/** The app sets this mark when its first figure is drawn (the new lesson engine does). */
export const FIRST_DRAW_MARK = 'spline-lab:first-draw';

/** How the load time was taken, for the printout. */
export const FALLBACK_METHOD =
  'a `.figure canvas` laid out with non-zero width + 2 animation frames';

// tsx (esbuild, keepNames) wraps named functions in `__name(...)`, and that
// also reaches code Playwright sends to the page: give the page a harmless one.
const NAME_SHIM = 'globalThis.__name = globalThis.__name || ((f) => f);';

// Runs before the app: `__benchFigure` resolves with performance.now() once a
// figure canvas has a width and two frames have passed (checked once a frame
// for at most 15 s from navigation, then it stops and resolves null).
const FIGURE_WATCH = `
globalThis.__benchFigure = new Promise((resolve) => {
  const tick = () => {
    const canvas = Array.from(document.querySelectorAll('.figure canvas')).find(
      (c) => c.getBoundingClientRect().width > 0,
    );
    if (canvas) requestAnimationFrame(() => requestAnimationFrame(() => resolve(performance.now())));
    else if (performance.now() < 15000) requestAnimationFrame(tick);
    else resolve(null);
  };
  requestAnimationFrame(tick);
});
`;

export function launchBrowser(): Promise<Browser> {
  return chromium.launch({
    executablePath: process.env.CHROMIUM_PATH || '/usr/bin/chromium',
    args: chromiumArgs,
  });
}

/**
 * A fresh context (no cache, no storage) at the benchmark screen. The app's
 * service worker is blocked, so it never answers a fetch nor installs during a
 * measurement; the figure watcher is left out of pages that must stay idle.
 */
export async function freshContext(
  browser: Browser,
  { watchFigure = true }: { watchFigure?: boolean } = {},
): Promise<BrowserContext> {
  const context = await browser.newContext({ ...SCREEN, serviceWorkers: 'block' });
  await context.addInitScript(watchFigure ? NAME_SHIM + FIGURE_WATCH : NAME_SHIM);
  return context;
}

/** Resolves after the page's next animation frame and the one after it. */
export function nextFrames(page: Page): Promise<void> {
  return page.evaluate(
    () =>
      new Promise<void>((resolve) =>
        requestAnimationFrame(() => requestAnimationFrame(() => resolve())),
      ),
  );
}

/** Waits for the watcher's first figure; false if none appeared. */
export async function figureDrawn(page: Page): Promise<boolean> {
  const at = await page.evaluate(
    () => (globalThis as unknown as { __benchFigure: Promise<number | null> }).__benchFigure,
  );
  return at !== null;
}

/** When the first figure was drawn, in ms from navigation: the app's mark, else the watcher. */
export function firstDrawTime(
  page: Page,
  markWaitMs: number,
): Promise<{ mark: number | null; drawn: number | null }> {
  return page.evaluate(
    ({ name, waitMs }) =>
      new Promise<{ mark: number | null; drawn: number | null }>((resolve) => {
        const watched = (globalThis as unknown as { __benchFigure: Promise<number | null> })
          .__benchFigure;
        let drawn: number | null = null;
        let drawnAt: number | null = null;
        void watched.then((t) => {
          drawn = t;
          drawnAt = performance.now();
        });
        const check = () => {
          const mark = performance.getEntriesByName(name)[0]?.startTime ?? null;
          if (mark !== null || (drawnAt !== null && performance.now() - drawnAt >= waitMs))
            resolve({ mark, drawn });
          else setTimeout(check, 10);
        };
        check();
      }),
    { name: FIRST_DRAW_MARK, waitMs: markWaitMs },
  );
}
