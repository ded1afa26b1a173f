/**
 * Teaching from the front: undo keeps the step, the clicker runs from one
 * scene into the next, one finger scrolls a phone's page, the presenter's
 * tools. The rules checked on every lesson of the registry (the clicker
 * whatever has focus, presenter view legible from the back row, the blank
 * screen) are in clicker.ts, run by keyboard.spec.ts and pictures.spec.ts on
 * the pages they open anyway.
 */
import type { Page } from '@playwright/test';
import { textsUnder } from './clicker';
import { expect, hashState, settled, test, linkState } from './fixtures';

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
  // No layer over the figures until there is ink: a blank one costs every frame a copy of it.
  await expect(ink).toBeHidden();
  await page.keyboard.press('i');
  await expect(ink).toBeVisible();
  await page.mouse.move(box.x + 100, box.y + 100);
  await page.mouse.down();
  await page.mouse.move(box.x + 300, box.y + 200, { steps: 8 });
  await page.mouse.up();
  expect(await inked()).toBeGreaterThan(100);
  await page.keyboard.press('PageUp');
  await settled(page);
  expect(await inked()).toBe(0);
  await page.keyboard.press('i');
  await expect(ink).toBeHidden();
});

test('Q asks the room to predict the next step; the next press reveals it', async ({ page }) => {
  await page.goto('./#/de-casteljau?p=0,0;1,2;3,2;4,0&t=0.5&step=1');
  await settled(page);
  await page.keyboard.press('p');
  const caption = page.locator('.caption');
  const step = caption.locator('.caption-step');
  await expect(step).toHaveText(/^Join them in order/);
  await page.keyboard.press('q');
  await expect(step).toHaveText('Predict before the next press: what will step 2 show, and why?');
  await expect(caption).toHaveClass(/asking/);
  // Asking changes no step: the figure still shows step 1.
  expect((await linkState(page)).step).toBe('1');
  await page.keyboard.press('PageDown');
  await expect(step).toHaveText(/^Level 1/);
  await expect(caption).not.toHaveClass(/asking/);
  expect((await linkState(page)).step).toBe('2');
});

test.describe('at 1920 × 1080', () => {
  test.use({ viewport: { width: 1920, height: 1080 } });

  /** Each shown figure's box on the page. */
  const boxes = (page: Page) =>
    page.evaluate(() =>
      Object.fromEntries(
        [...document.querySelectorAll<HTMLCanvasElement>('canvas[data-figure]')]
          .filter((c) => c.offsetParent !== null)
          .map((c) => {
            const b = c.getBoundingClientRect();
            return [c.dataset.figure!, { x: b.x, y: b.y, w: b.width, h: b.height }];
          }),
      ),
    );

  test('presenter view puts a tall subject’s plot beside it for the whole scene, a wide one’s under it', async ({
    page,
  }) => {
    // Long gradients: the patch and its arrows are about as tall as wide.
    await page.goto('./#/hermite?scene=long&step=0');
    await settled(page);
    let b = await boxes(page);
    expect(b.basis.y).toBeGreaterThanOrEqual(b.patches.y + b.patches.h - 1);
    await page.keyboard.press('p');
    await settled(page);
    b = await boxes(page);
    // Beside it, as tall, and the patch is given the figures' whole height.
    expect(b.basis.x).toBeGreaterThanOrEqual(b.patches.x + b.patches.w - 1);
    expect(Math.abs(b.basis.y - b.patches.y)).toBeLessThan(2);
    expect(b.patches.h).toBeGreaterThan(700);
    // Through every step of the scene the figures keep that arrangement and size.
    for (let k = 1; k <= 7; k++) {
      await page.keyboard.press('PageDown');
      await settled(page);
      expect(await boxes(page)).toEqual(b);
    }
    // D₁'s handle (off the figure under the wide arrangement) is on it.
    const handle = (await page.getByRole('button', { name: /^D1 at/ }).boundingBox())!;
    expect(handle.x + handle.width / 2).toBeLessThan(b.patches.x + b.patches.w);
    expect(handle.y + handle.height / 2).toBeLessThan(b.patches.y + b.patches.h);
    // Five points across the screen: the plot stays under the patches.
    await page.goto('./#/hermite?scene=several&step=0');
    await settled(page);
    b = await boxes(page);
    expect(b.basis.y).toBeGreaterThanOrEqual(b.patches.y + b.patches.h - 1);
    // Back at the long gradients, beside again; leaving presenter view takes the lesson's own arrangement back.
    await page.goto('./#/hermite?scene=long&step=0');
    await settled(page);
    expect((await boxes(page)).basis.x).toBeGreaterThan(1000);
    await page.keyboard.press('p');
    await settled(page);
    b = await boxes(page);
    expect(b.basis.y).toBeGreaterThanOrEqual(b.patches.y + b.patches.h - 1);
  });
});

test('on a 1024×768 projector a caption formula too wide for the screen takes lines, none of it under 28 px', async ({
  page,
}) => {
  // The four Hermite terms and their sum at μ = 0.3: shrunk to fit 992 px,
  // its indices came out at 17 px.
  await page.setViewportSize({ width: 1024, height: 768 });
  await page.goto('./#/blending?scene=hermite&p=0,0;1,2;3,2;4,0&mu=0.3&b=hermite&step=7');
  await settled(page);
  await page.keyboard.press('p');
  await settled(page);
  const formula = page.locator('[data-caption] .caption-formula [data-fit]');
  await expect(formula).toHaveClass(/wraps/);
  expect(await textsUnder(page, 28)).toEqual([]);
  // Seen whole: set on lines, not scrolled in its box.
  const scrolled = await formula.evaluate((el) => el.scrollWidth - el.clientWidth);
  expect(scrolled).toBeLessThanOrEqual(1);
});
