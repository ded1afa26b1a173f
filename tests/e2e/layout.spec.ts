import type { Page } from '@playwright/test';
import { expect, lessonFolders, settled, test } from './fixtures';

/**
 * Watches for writes that the page must be laid out for (a text, children,
 * a style, a class, `hidden`, a field's value) and that land outside every layout boundary:
 * an element with size and layout containment (a live number's box, a
 * slider's slot, a net cell's field). Chromium then lays out the whole
 * document to draw the frame. A write inside a boundary lays out that box.
 * Handles' keyboard stand-ins are positioned out of flow, and hidden
 * elements are laid out by nobody: neither counts.
 */
async function watchLooseWrites(page: Page): Promise<void> {
  await page.evaluate(() => {
    const w = window as unknown as {
      loose: Map<string, Set<number>>;
      looseWatch: MutationObserver;
      looseFrame: number;
      looseTick: number;
    };
    const where = (e: Element) => {
      const parts: string[] = [];
      for (let i = 0, at: Element | null = e; at && i < 4; i++, at = at.parentElement)
        parts.unshift(at.tagName.toLowerCase() + (at.classList[0] ? `.${at.classList[0]}` : ''));
      return parts.join('>');
    };
    const bounded = (e: Element) => {
      for (let at: Element | null = e; at; at = at.parentElement) {
        const contain = getComputedStyle(at).contain;
        if (contain === 'strict' || (contain.includes('size') && contain.includes('layout')))
          return true;
      }
      return false;
    };
    w.loose = new Map();
    w.looseFrame = 0;
    // A field's value is no attribute: each frame, the fields whose value changed.
    const fields = [...document.querySelectorAll('input')].filter(
      (f) => !['checkbox', 'radio', 'button'].includes(f.type) && f.getClientRects().length > 0,
    );
    const values = fields.map((f) => f.value);
    const tick = () => {
      w.looseFrame++;
      fields.forEach((f, i) => {
        if (f.value === values[i]) return;
        values[i] = f.value;
        if (bounded(f)) return;
        const key = `${where(f)} value`;
        if (!w.loose.has(key)) w.loose.set(key, new Set());
        w.loose.get(key)!.add(w.looseFrame);
      });
      w.looseTick = requestAnimationFrame(tick);
    };
    w.looseTick = requestAnimationFrame(tick);
    w.looseWatch = new MutationObserver((records) => {
      for (const r of records) {
        const e = (r.target.nodeType === 1 ? r.target : r.target.parentElement) as Element | null;
        if (!e || !e.isConnected || e.closest('.handle-layer') || e.getClientRects().length === 0)
          continue;
        if (bounded(e)) continue;
        const key = `${where(e)} ${r.type === 'attributes' ? `[${r.attributeName}]` : 'text'}`;
        if (!w.loose.has(key)) w.loose.set(key, new Set());
        w.loose.get(key)!.add(w.looseFrame);
      }
    });
    w.looseWatch.observe(document.body, {
      subtree: true,
      childList: true,
      characterData: true,
      attributes: true,
      attributeFilter: ['style', 'class', 'hidden'],
    });
  });
}

/** The places written outside a boundary on more than `most` frames, with how many; stops watching. */
async function looseWrites(page: Page, most: number): Promise<string[]> {
  return page.evaluate((most) => {
    const w = window as unknown as {
      loose: Map<string, Set<number>>;
      looseWatch: MutationObserver;
      looseTick: number;
    };
    w.looseWatch.takeRecords();
    w.looseWatch.disconnect();
    cancelAnimationFrame(w.looseTick);
    return [...w.loose]
      .filter(([, frames]) => frames.size > most)
      .map(([key, frames]) => `${key} on ${frames.size} frames`);
  }, most);
}

const MOVES = 12;

for (const slug of lessonFolders()) {
  test(`${slug}: a drag lays out what it changed, not the page round it`, async ({ page }) => {
    await page.setViewportSize({ width: 1920, height: 1080 });
    await page.goto(`./#/${slug}`);
    await settled(page);
    const controls: [string, ReturnType<Page['locator']>][] = [
      ['the first point', page.locator('.handle-proxy').first()],
    ];
    const sliders = page.locator('input[type=range]');
    for (let i = 0; i < (await sliders.count()); i++)
      if (await sliders.nth(i).isVisible())
        controls.push([
          `slider ${await sliders.nth(i).getAttribute('aria-label')}`,
          sliders.nth(i),
        ]);
    for (const [what, control] of controls) {
      await control.scrollIntoViewIfNeeded();
      const box = (await control.boundingBox())!;
      const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
      await page.mouse.move(x, y);
      await page.mouse.down();
      await watchLooseWrites(page);
      for (let k = 1; k <= MOVES; k++) {
        const slider = what.startsWith('slider');
        await page.mouse.move(x + (slider ? -4 * k : 5 * k), y + (slider ? 0 : (k % 2) * 4));
        await page.evaluate(() => new Promise((done) => requestAnimationFrame(done)));
      }
      // A number that grows a digit resizes its box, and that lays out its
      // surroundings once; a place written on most frames lays out every one.
      const loose = await looseWrites(page, MOVES / 4);
      await page.mouse.up();
      await settled(page);
      expect(loose, `${slug}, dragging ${what}`).toEqual([]);
    }
  });
}
