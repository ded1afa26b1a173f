/**
 * Pictures that are checked, for every lesson and every scene, at its last
 * step, in normal view (1400×850) and presenter view (1920×1080):
 *
 * - no label covers another, leaves its figure or has a line or a point
 *   through its letters, from the painter's own placement data and record of
 *   its ink (what each frame recorded), not from pixels;
 * - every axis number sits at its tick, on its scale, read back from the
 *   figures' SVG export (axes.ts);
 * - every live formula has its numbers filled in (what a screen reader reads);
 * - in presenter view, the caption's formula is seen whole, not cut at its foot,
 *   no step's caption is taller than the 24% of the screen a caption reserves,
 *   and the figures keep one size through every step of a scene;
 * - the drawing matches its reviewed reference image (Playwright's
 *   toHaveScreenshot, with a small tolerance). The comparison is of the
 *   figures with their labels hidden (presenter key A): what is compared is
 *   the drawing itself, which does not depend on the machine's fonts.
 *
 * After an intended change to a drawing, look at the new pictures and update
 * the references deliberately:
 *   node scripts/e2e.mjs tests/e2e/pictures.spec.ts --update-snapshots
 */
import type { Page } from '@playwright/test';
import { exportedDrawing, tickProblems } from './axes';
import { captionUnderCorner, legibleFromTheBackRow, textsUnder } from './clicker';
import {
  expect,
  figureSizes,
  inLecturesLetter,
  LECTURE_LETTER_LESSONS,
  lessonFolders,
  settled,
  test,
} from './fixtures';

const slugs = lessonFolders();

interface Placed {
  figure: string;
  width: number;
  height: number;
  labels: { text: string; x: number; y: number; width: number; height: number }[];
  /** Labels a stroke or a point of the same frame runs through, by the painter's record of its ink. */
  crossed: string[];
}

/**
 * Labels on top of each other (by more than a pixel each way), outside their
 * figure, or with a line or a point running through their letters, in the
 * figures on screen.
 */
async function labelProblems(page: Page): Promise<string[]> {
  const figures = await page.evaluate(() => {
    const shown = new Set(
      [...document.querySelectorAll<HTMLCanvasElement>('canvas[data-figure]')]
        .filter((c) => c.checkVisibility())
        .map((c) => c.dataset.figure),
    );
    return (window as unknown as { splineLab: { labels(): Placed[] } }).splineLab
      .labels()
      .filter((f) => shown.has(f.figure));
  });
  const problems: string[] = [];
  for (const { figure, width, height, labels, crossed } of figures) {
    for (const line of crossed) problems.push(`${figure}: ${line}`);
    for (const b of labels)
      if (b.x < -1 || b.y < -1 || b.x + b.width > width + 1 || b.y + b.height > height + 1)
        problems.push(`${figure}: “${b.text}” outside the figure`);
    for (let i = 0; i < labels.length; i++)
      for (let j = i + 1; j < labels.length; j++) {
        const a = labels[i];
        const b = labels[j];
        const w = Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x);
        const h = Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y);
        if (w > 1 && h > 1) problems.push(`${figure}: “${a.text}” on “${b.text}”`);
      }
  }
  return problems;
}

/** Is the caption taller than a caption may reserve (24% of the screen)? */
const captionOverReserve = (page: Page) =>
  page.evaluate(() => {
    const caption = document.querySelector('[data-caption]');
    return !!caption && caption.getBoundingClientRect().height > window.innerHeight * 0.24 + 1;
  });

for (const slug of slugs) {
  for (const mode of ['normal', 'presenter'] as const) {
    test(`${slug}, ${mode} view: every scene's labels stand clear, its formulas are filled in and its drawing matches the reference`, async ({
      page,
    }) => {
      test.setTimeout(90_000);
      // The reviewed pictures of the lessons that follow the lecture notes are in its letter, μ.
      if (LECTURE_LETTER_LESSONS.includes(slug)) await inLecturesLetter(page);
      if (mode === 'presenter') await page.setViewportSize({ width: 1920, height: 1080 });
      await page.goto(`./#/${slug}`);
      await settled(page);
      if (mode === 'presenter') {
        await page.keyboard.press('p');
        // Legible from the back row, and B blanks it (the presenter-view rules).
        await legibleFromTheBackRow(page, slug);
      }
      const scenes = page.locator('button[data-scene]');
      const ids = await scenes.evaluateAll((buttons) =>
        buttons.map((b) => b.getAttribute('data-scene')!),
      );
      const problems: string[] = [];
      for (const id of ids) {
        await page.evaluate((scene) => {
          document.querySelector<HTMLButtonElement>(`button[data-scene="${scene}"]`)!.click();
        }, id);
        if (mode === 'presenter') {
          // The figure keeps its size through the scene's steps (#19): the
          // caption holds the height of the scene's tallest step, and no step's
          // caption is taller than the 24% of the screen it may reserve. Read
          // from the page's boxes.
          await page.keyboard.press('Home');
          await settled(page);
          const status = (await page.locator('.step-status').textContent()) ?? '';
          const count = Number(/Step \d+\/(\d+)/.exec(status)?.[1] ?? 0);
          const sizes: string[] = [];
          for (let k = 0; k <= count; k++) {
            if (k > 0) {
              await page.keyboard.press('PageDown');
              await settled(page);
            }
            sizes.push(await figureSizes(page));
            // No text on the room's screen under 28 px at any step: a
            // formula's subscripts, or a formula shrunk to fit the caption.
            for (const small of await textsUnder(page, 28))
              problems.push(`${id}: step ${k} sets ${small}`);
            // Nothing of the caption under the lecturer's corner button (☰).
            for (const hidden of await captionUnderCorner(page))
              problems.push(`${id}: step ${k}'s caption has ${hidden} under the corner button`);
            if (await captionOverReserve(page))
              problems.push(`${id}: step ${k}'s caption is taller than its reserve`);
          }
          sizes.forEach((size, k) => {
            if (size !== sizes[0])
              problems.push(`${id}: step ${k}'s figures are ${size}, step 0's ${sizes[0]}`);
          });
        }
        await page.keyboard.press('End');
        await page.mouse.move(0, 0);
        await settled(page);
        for (const problem of await labelProblems(page)) problems.push(`${id}: ${problem}`);
        // Axis numbers at their ticks, read back from the drawing the SVG button saves.
        for (const problem of tickProblems(await exportedDrawing(page)))
          problems.push(`${id}: ${problem}`);
        // Live formulas are filled in, for screen readers too: no number slot
        // left as its marker (engine issue), whatever the shape of the scene's formulas.
        const unfilled = await page
          .locator('.katex')
          .evaluateAll((all) => all.filter((k) => k.textContent?.includes('§')).length);
        if (unfilled > 0) problems.push(`${id}: ${unfilled} formulas with unfilled number slots`);
        // The caption's formula is seen whole: not cut off at the caption's bottom edge.
        if (mode === 'presenter') {
          const cut = await page.evaluate(() => {
            const caption = document.querySelector('[data-caption]');
            const formula = caption?.querySelector('.caption-formula .katex-html');
            if (!caption || !formula || !formula.getClientRects().length) return 0;
            return formula.getBoundingClientRect().bottom - caption.getBoundingClientRect().bottom;
          });
          if (cut > 1)
            problems.push(`${id}: the caption's formula is cut ${Math.round(cut)} px short`);
          // The room's screen is the figure (#19): its canvases take at least
          // three quarters of the 1920 × 1080 screen, read from their boxes.
          const share = await page.evaluate(() => {
            const boxes = [...document.querySelectorAll('.stage-figures canvas[data-figure]')]
              .filter((c) => c.checkVisibility())
              .map((c) => c.getBoundingClientRect());
            const w =
              Math.max(...boxes.map((b) => b.right)) - Math.min(...boxes.map((b) => b.left));
            const h =
              Math.max(...boxes.map((b) => b.bottom)) - Math.min(...boxes.map((b) => b.top));
            return (w * h) / (window.innerWidth * window.innerHeight);
          });
          if (share < 0.75)
            problems.push(`${id}: the figure takes ${(share * 100).toFixed(0)}% of the screen`);
        }
        // The drawing, without the labels whose glyphs depend on the machine's fonts.
        await page.keyboard.press('a');
        await settled(page);
        await expect(page.locator('.stage-figures')).toHaveScreenshot(`${slug}-${id}-${mode}.png`, {
          maxDiffPixelRatio: 0.01,
          animations: 'disabled',
          caret: 'hide',
        });
        await page.keyboard.press('a');
      }
      // (A lesson's first formula may sit in a folded section: count, not look.)
      expect(await page.locator('.katex').count(), `${slug}: typeset formulas`).toBeGreaterThan(0);
      expect(problems, `${slug}, ${mode} view: labels and formulas`).toEqual([]);
    });
  }
}
