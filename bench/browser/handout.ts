// How long a whole-lesson handout (every step, 4 a page, A4) takes to make:
// from opening its link in a fresh page to every page drawn and its formulas
// fitted (the app's `handout-build` measure), with the frames and pages it made.
import type { Browser } from '@playwright/test';
import { freshContext } from './page';

export interface HandoutRow {
  lesson: string;
  frames: number;
  pages: number;
  /** From the handout's first plan to its last fitted formula (ms). */
  build: number;
  /** From opening the link to the handout ready, lesson code and fonts included (ms). */
  ready: number;
  note?: string;
}

export async function handoutTimes(
  browser: Browser,
  base: string,
  slug: string,
): Promise<HandoutRow> {
  const context = await freshContext(browser);
  try {
    const page = await context.newPage();
    const start = Date.now();
    await page.goto(`${base}#/${slug}/handout`);
    await page.waitForSelector('.handout[data-ready="true"]', { timeout: 60_000 });
    const ready = Date.now() - start;
    const figures = await page.evaluate(() => {
      const handout = document.querySelector<HTMLElement>('.handout')!;
      const build = performance.getEntriesByName('handout-build').at(-1);
      return {
        frames: Number(handout.dataset.frames),
        pages: Number(handout.dataset.pages),
        build: build ? build.duration : Number.NaN,
      };
    });
    return { lesson: slug, ...figures, ready };
  } catch (error) {
    const message = (error instanceof Error ? error.message : String(error)).split('\n')[0];
    return {
      lesson: slug,
      frames: 0,
      pages: 0,
      build: Number.NaN,
      ready: Number.NaN,
      note: message,
    };
  } finally {
    await context.close();
  }
}

/** The table, slowest first, and the longest lesson's figure against the 5 s budget. */
export function printHandouts(rows: readonly HandoutRow[]): void {
  console.log(
    '\nHandouts: every step, 4 frames a page, A4 (budget: under 5 s for the longest lesson)',
  );
  console.log('lesson               frames  pages   build ms   link→ready ms');
  for (const row of [...rows].sort((a, b) => b.frames - a.frames)) {
    if (row.note) {
      console.log(`${row.lesson.padEnd(20)} failed: ${row.note}`);
      continue;
    }
    console.log(
      `${row.lesson.padEnd(20)} ${String(row.frames).padStart(6)} ${String(row.pages).padStart(6)} ${row.build.toFixed(0).padStart(10)} ${row.ready.toFixed(0).padStart(15)}`,
    );
  }
  const longest = [...rows].filter((r) => !r.note).sort((a, b) => b.frames - a.frames)[0];
  if (longest)
    console.log(
      `Longest lesson (${longest.lesson}, ${longest.frames} frames): ${(longest.ready / 1000).toFixed(2)} s from its link to every page ready ${longest.ready < 5000 ? '(under 5 s)' : '(OVER the 5 s budget)'}.`,
    );
}
