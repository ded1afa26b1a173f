/**
 * Teaching from the front, for every lesson in the registry: the clicker
 * steps whatever has focus, presenter view is legible from the back row, the
 * screen blanks, one finger scrolls a phone's page. Expected behaviour comes
 * from the rules (one step per press, values untouched, ≥ 28 px), read
 * from the link and the DOM, never from the app's own verdicts.
 */
import type { Locator, Page } from '@playwright/test';
import { expect, hashState, lessonFolders, settled, snapshot, test, linkState } from './fixtures';

const slugs = lessonFolders();

/** The link's fields without the views (a pan is not a step). */
function fields(page: Page): Record<string, string> {
  return Object.fromEntries(
    Object.entries(hashState(page)).filter(([key]) => !key.startsWith('view.')),
  );
}

/** What changed between two links, as `key: before → after`. */
function changes(a: Record<string, string>, b: Record<string, string>): string[] {
  const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
  return [...keys].filter((k) => a[k] !== b[k]).map((k) => `${k}: ${a[k]} → ${b[k]}`);
}

/** One clicker press forward: the step field went up by one, or the scene changed (to its step 0). */
function isOneStepForward(before: Record<string, string>, after: Record<string, string>): boolean {
  const changed = changes(before, after);
  if (before.scene !== after.scene) return true;
  if (changed.length !== 1) return false;
  const key = changed[0].split(':')[0];
  return Number(after[key]) === Number(before[key]) + 1;
}

/** The value a control shows, to check a clicker key left it alone. */
async function valueOf(control: Locator, kind: string): Promise<string> {
  // A point: the one that has focus (the list of points may grow with the step).
  if (kind === 'point')
    return control.page().evaluate(() => document.activeElement?.getAttribute('aria-label') ?? '');
  return control.evaluate((el) => {
    if (el instanceof HTMLInputElement)
      return el.type === 'checkbox' || el.type === 'radio' ? String(el.checked) : el.value;
    return el.getAttribute('aria-label') ?? el.textContent ?? '';
  });
}

/** The kinds of control a lesson page has, each the first of its kind that is visible. */
function controls(page: Page): [string, Locator][] {
  const lesson = page.locator('.lesson-page');
  return [
    ['slider', lesson.locator('input[type=range]:visible').first()],
    ['number field', lesson.locator('input[type=number]:visible').first()],
    ['checkbox', lesson.locator('input[type=checkbox]:visible').first()],
    ['radio button', lesson.locator('input[type=radio]:visible').first()],
    ['scene button', lesson.locator('button[data-scene]').first()],
    ['step button', lesson.getByRole('button', { name: 'Next ▶' })],
    ['point', lesson.locator('.handle-proxy').first()],
  ];
}

for (const slug of slugs) {
  test(`${slug}: PageDown and PageUp step once whatever has focus, and leave the control alone`, async ({
    page,
  }) => {
    // The first scene at its first step: there is always a next step.
    await page.goto(`./#/${slug}`);
    await page.locator('button[data-scene]').first().click();
    await settled(page);
    let tried = 0;
    /** The link's field that holds the step, as the first press shows it. */
    let stepKey: string | null = null;
    for (const [kind, control] of controls(page)) {
      if ((await control.count()) === 0) continue;
      tried++;
      await control.focus();
      const value = await valueOf(control, kind);
      const before = fields(page);
      await page.keyboard.press('PageDown');
      await settled(page);
      const after = fields(page);
      expect(
        isOneStepForward(before, after),
        `${slug}, focus on a ${kind}: one step forward (${changes(before, after).join('; ')})`,
      ).toBe(true);
      // A new scene sets its own values; within a scene nothing else may move.
      if (before.scene === after.scene) {
        stepKey = changes(before, after)[0].split(':')[0];
        expect(await valueOf(control, kind), `${slug}: the ${kind} kept its value`).toBe(value);
      }
      await page.keyboard.press('PageUp');
      await settled(page);
      expect(changes(before, fields(page)), `${slug}, ${kind}: PageUp went back`).toEqual([]);
      expect(await valueOf(control, kind), `${slug}: the ${kind} kept its value`).toBe(value);
    }
    expect(tried).toBeGreaterThanOrEqual(2);

    // A checkbox's own key is Space: it ticks the box and does not step.
    const box = page.locator('.lesson-page input[type=checkbox]:visible').first();
    if ((await box.count()) > 0 && stepKey !== null) {
      await box.focus();
      const checked = await box.isChecked();
      const before = fields(page);
      await page.keyboard.press(' ');
      await settled(page);
      expect(await box.isChecked()).toBe(!checked);
      const after = fields(page);
      // The box's own change only (a lesson may show a new option's whole
      // construction with it), never the clicker's one step and nothing more.
      const changed = changes(before, after);
      expect(changed.length > 0, 'Space ticked the box').toBe(true);
      expect(
        changed.length === 1 && changed[0].startsWith(`${stepKey}:`),
        `Space on a checkbox does not step (${changed.join('; ')})`,
      ).toBe(false);
      expect(after.scene).toBe(before.scene);
    }
  });

  test(`${slug}: presenter view at 1920×1080 is legible from the back row`, async ({ page }) => {
    await page.setViewportSize({ width: 1920, height: 1080 });
    await page.goto(`./#/${slug}`);
    await page.keyboard.press('p');
    await expect(page.locator('html')).toHaveClass(/projector/);
    await page.keyboard.press('PageDown');
    await settled(page);
    // The side panel is folded away and the caption is on screen.
    await expect(page.getByRole('complementary', { name: 'Explanation' })).toBeHidden();
    const caption = page.locator('[data-caption]');
    await expect(caption).toBeInViewport({ ratio: 1 });
    await expect(caption).not.toHaveText('');
    const small = await page.evaluate(() => {
      const found: string[] = [];
      const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
      for (let node = walker.nextNode(); node; node = walker.nextNode()) {
        const el = node.parentElement;
        // Zero-width characters (KaTeX's struts) are not text anyone reads.
        if (!el || !/[^\s\u200b-\u200f\u2060\ufeff]/.test(node.textContent ?? '')) continue;
        if (el.closest('.katex-mathml, .visually-hidden, [hidden], dialog:not([open])')) continue;
        const box = el.getBoundingClientRect();
        if (box.width === 0 || box.height === 0 || el.checkVisibility?.() === false) continue;
        const size = parseFloat(getComputedStyle(el).fontSize);
        if (size < 28)
          found.push(`${size.toFixed(1)}px “${(node.textContent ?? '').trim().slice(0, 30)}”`);
      }
      return found;
    });
    expect(small, 'texts under 28 px').toEqual([]);
    await snapshot(page, `presenter-${slug}`);

    // B blanks the screen; a clicker key brings it back without stepping.
    const before = fields(page);
    await page.keyboard.press('b');
    const cover = page.locator('[data-blank]');
    await expect(cover).toBeVisible();
    await expect(cover).toBeInViewport({ ratio: 1 });
    await page.keyboard.press('PageDown');
    await expect(cover).toBeHidden();
    await settled(page);
    expect(changes(before, fields(page))).toEqual([]);
  });
}

test('undo is for edits: it restores the point and keeps the step', async ({ page }) => {
  await page.goto('./#/de-casteljau?p=0,0;1,2;3,2;4,0&t=0.5&step=1');
  await settled(page);
  const point = page.getByRole('button', { name: /^P1 at/ });
  await point.focus();
  await page.keyboard.press('ArrowRight');
  await settled(page);
  const moved = (await linkState(page)).p;
  expect(moved).not.toBe('0,0;1,2;3,2;4,0');
  await page.keyboard.press('PageDown');
  await settled(page);
  expect((await linkState(page)).step).toBe('2');
  await page.keyboard.press('Control+z');
  await settled(page);
  expect((await linkState(page)).p).toBe('0,0;1,2;3,2;4,0');
  expect((await linkState(page)).step).toBe('2');
});

test('past the last step the clicker opens the next scene at its first step, and the link says which', async ({
  page,
}) => {
  await page.goto('./#/de-casteljau');
  await page.locator('button[data-scene]').first().click();
  await page.keyboard.press('End');
  await settled(page);
  const first = (await linkState(page)).scene;
  await page.keyboard.press('PageDown');
  await settled(page);
  const second = (await linkState(page)).scene;
  expect(second).not.toBe(first);
  expect((await linkState(page)).step).toBe('0');
  await expect(page.locator(`button[data-scene="${second}"]`)).toHaveAttribute(
    'aria-pressed',
    'true',
  );
  // Back again: the first scene at its last step, as it was left.
  await page.keyboard.press('PageUp');
  await settled(page);
  expect((await linkState(page)).scene).toBe(first);
  await page.reload();
  await settled(page);
  expect((await linkState(page)).scene).toBe(first);
});

test.describe('on a phone', () => {
  test.use({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });

  test('one finger swiping up over a figure scrolls the page and leaves the view alone', async ({
    page,
  }) => {
    await page.goto('./#/de-casteljau');
    await settled(page);
    const box = (await page.locator('canvas[data-figure]').first().boundingBox())!;
    // Low on the figure, left of the curve: empty space, no point within reach.
    const x = box.x + box.width * 0.08;
    const y0 = box.y + box.height * 0.9;
    const cdp = await page.context().newCDPSession(page);
    await cdp.send('Input.dispatchTouchEvent', {
      type: 'touchStart',
      touchPoints: [{ x, y: y0 }],
    });
    for (let i = 1; i <= 10; i++)
      await cdp.send('Input.dispatchTouchEvent', {
        type: 'touchMove',
        touchPoints: [{ x, y: y0 - i * 30 }],
      });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await expect.poll(() => page.evaluate(() => window.scrollY)).toBeGreaterThan(100);
    await settled(page);
    expect(Object.keys(hashState(page)).filter((k) => k.startsWith('view.'))).toEqual([]);
  });
});

/** The figure's pixels, to compare pictures of the same state. */
const pixels = (page: Page) =>
  page
    .locator('canvas[data-figure]')
    .first()
    .evaluate((c) => {
      // A short fingerprint of the picture (FNV-1a over its PNG), not the picture itself.
      const url = (c as HTMLCanvasElement).toDataURL();
      let h = 0x811c9dc5;
      for (let i = 0; i < url.length; i++) h = Math.imul(h ^ url.charCodeAt(i), 0x01000193);
      return `${url.length}:${(h >>> 0).toString(16)}`;
    });

test('presenter tools: hide and reveal the curve, ghost, laser, ink cleared by the next step', async ({
  page,
}) => {
  await page.goto('./#/de-casteljau?p=0,0;1,2;3,2;4,0&t=0.5&step=5');
  await page.mouse.move(0, 0);
  await settled(page);
  const shown = await pixels(page);
  // Predict, then show: C hides the curve (the picture changes), C again brings it back.
  await page.keyboard.press('c');
  await settled(page);
  const hidden = await pixels(page);
  expect(hidden).not.toBe(shown);
  await page.keyboard.press('c');
  await settled(page);
  expect(await pixels(page)).toBe(shown);

  // A ghost of the figure stays faintly behind a change, and goes with the tool.
  await page.keyboard.press('o');
  await page.goto('./#/de-casteljau?p=0,0;1,3;3,3;4,0&t=0.5&step=5');
  await settled(page);
  const withGhost = await pixels(page);
  await page.keyboard.press('o');
  await settled(page);
  expect(await pixels(page)).not.toBe(withGhost);

  // The laser: a bright dot where the pointer is.
  const box = (await page.locator('canvas[data-figure]').first().boundingBox())!;
  await page.keyboard.press('l');
  await page.mouse.move(box.x + 200, box.y + 150);
  const dot = page.locator('.laser-dot');
  await expect(dot).toBeVisible();
  const at = (await dot.boundingBox())!;
  expect(Math.abs(at.x + at.width / 2 - (box.x + 200))).toBeLessThan(3);
  expect(Math.abs(at.y + at.height / 2 - (box.y + 150))).toBeLessThan(3);
  await page.keyboard.press('l');

  // Ink: a stroke over the figure, wiped when the step changes.
  const ink = page.locator('[data-ink]');
  const inked = () =>
    ink.evaluate((c) => {
      const canvas = c as HTMLCanvasElement;
      const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
      let n = 0;
      for (let i = 3; i < data.length; i += 4) if (data[i] > 0) n++;
      return n;
    });
  await page.keyboard.press('i');
  await page.mouse.move(box.x + 100, box.y + 100);
  await page.mouse.down();
  await page.mouse.move(box.x + 300, box.y + 200, { steps: 8 });
  await page.mouse.up();
  expect(await inked()).toBeGreaterThan(100);
  await page.keyboard.press('PageUp');
  await settled(page);
  expect(await inked()).toBe(0);
});
