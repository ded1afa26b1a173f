// What opening the app costs: the JS it fetches (gzip) and the time from
// navigation to the first drawn figure.
import type { Browser, Page, Response } from '@playwright/test';
import { gzipSync } from 'node:zlib';
import { firstDrawTime, freshContext } from './page';

export interface ScriptFile {
  /** Path on the server, e.g. "/assets/index-abc.js". */
  readonly path: string;
  readonly bytes: number;
  readonly gzip: number;
}

export interface LoadTimes {
  /** ms from navigation to the first drawn figure, one per load. */
  readonly times: readonly number[];
  /** How many of them came from the app's own mark (the rest from the watcher). */
  readonly byMark: number;
}

const CARD = 'a.card[data-slug]';

/** Opens the gallery fresh: the lessons it links to and the JS it fetched. */
export async function openGallery(
  browser: Browser,
  base: string,
): Promise<{ slugs: string[]; scripts: ScriptFile[] }> {
  const context = await freshContext(browser);
  try {
    const page = await context.newPage();
    const scripts = collectScripts(page);
    await page.goto(`${base}#/`);
    await page.waitForLoadState('networkidle');
    const slugs = await page.$$eval(CARD, (cards) =>
      cards.map((card) => (card as HTMLElement).dataset.slug ?? ''),
    );
    return { slugs: slugs.filter((slug) => slug !== ''), scripts: await scripts() };
  } finally {
    await context.close();
  }
}

/** The JS fetched when a lesson is opened from the gallery (its card clicked). */
export async function lessonScripts(
  browser: Browser,
  base: string,
  slug: string,
): Promise<ScriptFile[]> {
  const context = await freshContext(browser);
  try {
    const page = await context.newPage();
    await page.goto(`${base}#/`);
    await quiet(page, 300);
    const scripts = collectScripts(page);
    await page.locator(`${CARD}[data-slug="${slug}"]`).click();
    await page.locator('.figure canvas').first().waitFor();
    await quiet(page, 300);
    return await scripts();
  } finally {
    await context.close();
  }
}

/** Loads `#/<slug>` in `runs` fresh contexts; waits up to `markWaitMs` for the app's mark. */
export async function loadTimes(
  browser: Browser,
  base: string,
  slug: string,
  runs: number,
  markWaitMs: number,
): Promise<LoadTimes> {
  const times: number[] = [];
  let byMark = 0;
  for (let run = 0; run < runs; run++) {
    // A first visit, which the service worker would not control yet; it is
    // blocked so that its install does not compete for the two cores.
    const context = await freshContext(browser);
    try {
      const page = await context.newPage();
      await page.goto(`${base}#/${slug}`, { waitUntil: 'commit' });
      const { mark, drawn } = await firstDrawTime(page, markWaitMs);
      if (mark !== null) byMark++;
      const time = mark ?? drawn;
      if (time !== null) times.push(time);
    } finally {
      await context.close();
    }
  }
  return { times, byMark };
}

/** Starts noting the page's .js responses; the returned function gzips what came. */
function collectScripts(page: Page): () => Promise<ScriptFile[]> {
  const responses: Response[] = [];
  page.on('response', (response) => {
    if (new URL(response.url()).pathname.endsWith('.js')) responses.push(response);
  });
  return async () =>
    Promise.all(
      responses.map(async (response) => {
        const body = await response.body();
        return {
          path: new URL(response.url()).pathname,
          bytes: body.length,
          gzip: gzipSync(body).length,
        };
      }),
    );
}

/** Waits until the page has requested nothing for `ms` (at most 5 s). */
async function quiet(page: Page, ms: number): Promise<void> {
  let last = Date.now();
  const onRequest = () => void (last = Date.now());
  page.on('request', onRequest);
  const giveUp = Date.now() + 5000;
  while (Date.now() - last < ms && Date.now() < giveUp) await page.waitForTimeout(50);
  page.off('request', onRequest);
}
