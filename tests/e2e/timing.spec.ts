/**
 * Frame-time tests: they run on their own, after every other browser test
 * (the "timing" project in playwright.config.ts), one at a time, so that what
 * they time is the app and not a second test sharing the two cores.
 */
import type { Page } from '@playwright/test';
import { expect, lessonSlugs, test } from './fixtures';

const nextFrame = (page: Page) =>
  page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

/**
 * Starts collecting the work of each frame (derive, draw, panel: the page
 * measures it as `spline-lab:frame`) that took over 50 ms.
 */
async function watchLongFrames(page: Page): Promise<void> {
  await page.evaluate(() => {
    const store = window as unknown as { longFrames: number[]; frames: number };
    store.longFrames = [];
    store.frames = 0;
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) {
        store.frames++;
        if (entry.duration > 50) store.longFrames.push(entry.duration);
      }
    }).observe({ type: 'measure' });
  });
}

/** The long frames seen, after checking that frames were measured at all. */
const longFrames = async (page: Page) => {
  const { longFrames, frames } = await page.evaluate(() => {
    const store = window as unknown as { longFrames: number[]; frames: number };
    return { longFrames: store.longFrames, frames: store.frames };
  });
  expect(frames, 'frames measured').toBeGreaterThan(0);
  return longFrames;
};

/** Opens the preset with the most movable points (the busiest figure). */
async function openBusiestPreset(page: Page): Promise<void> {
  const presets = page.locator('[data-scene]');
  const count = await presets.count();
  let best = -1;
  let most = -1;
  for (let i = 0; i < count; i++) {
    await presets.nth(i).click();
    await nextFrame(page);
    const handles = await page.locator('.handle-proxy').count();
    if (handles > most) {
      most = handles;
      best = i;
    }
  }
  if (best >= 0) await presets.nth(best).click();
  await nextFrame(page);
}

test.describe.configure({ mode: 'serial' });

test('zooming 40 notches in and out keeps every frame under 50 ms, on every lesson', async ({
  page,
}) => {
  test.setTimeout(360_000);
  for (const slug of await lessonSlugs(page)) {
    await page.goto(`./#/${slug}`);
    await expect(page.locator('canvas').first()).toBeVisible();
    await openBusiestPreset(page);
    const canvas = page.locator('.figure-geometry canvas, .figure-space canvas').first();
    if ((await canvas.count()) === 0) continue;
    const box = (await canvas.boundingBox())!;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await watchLongFrames(page);
    // 40 notches each way, five to a wheel event (a fast flick): the same
    // zoom range as one notch per frame, in a fifth of the frames.
    for (const direction of [-1, 1]) {
      for (let flick = 0; flick < 8; flick++) {
        await page.mouse.wheel(0, direction * 600);
        await nextFrame(page);
      }
    }
    expect(await longFrames(page), `${slug}: frames over 50 ms`).toEqual([]);
  }
});

test('a link to points a million units apart opens without a long frame, on every lesson', async ({
  page,
}) => {
  test.setTimeout(120_000);
  for (const slug of await lessonSlugs(page)) {
    await page.goto(`./#/${slug}`);
    await expect(page.locator('canvas').first()).toBeVisible();
    // Zoom in first: the far point must not make the kept view expensive.
    const canvas = page.locator('.figure-geometry canvas').first();
    if (await canvas.count()) {
      const box = (await canvas.boundingBox())!;
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      for (let notch = 0; notch < 30; notch++) await page.mouse.wheel(0, -120);
    }
    await nextFrame(page);
    await expect.poll(() => new URL(page.url()).hash).toContain('?');
    const hash = new URL(page.url()).hash;
    // The first list of 2D points in the link: its last point goes a million units away.
    const far = hash.replace(/=(-?[\d.]+,-?[\d.]+(?:;-?[\d.]+,-?[\d.]+)+)/, (_, list: string) => {
      const points = list.split(';');
      points[points.length - 1] = '1000000,-1000000';
      return `=${points.join(';')}`;
    });
    if (far === hash) continue;
    await watchLongFrames(page);
    await page.evaluate((h) => (location.hash = h), far);
    await expect.poll(() => new URL(page.url()).hash).toContain('1000000');
    for (let i = 0; i < 5; i++) await nextFrame(page);
    expect(await longFrames(page), `${slug}: frames over 50 ms`).toEqual([]);
  }
});
