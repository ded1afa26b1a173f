/**
 * A monkey on every lesson, and the frame budget under the heaviest input.
 * First the lesson's busiest preset is zoomed 40 notches in and out; then a
 * seeded random run of drags, wheel zooms far in and out, keys and control
 * clicks; last a link that sends a point a million units away. Throughout: no
 * error (the fixture) and no frame over 50 ms; afterwards no NaN, Infinity or
 * undefined in any text, and the state round-trips through its link (the same
 * state and, fitted, the same picture). It runs in the "timing" project:
 * alone, after the other browser tests, so that it times the app and not a
 * second test sharing the two cores.
 */
import type { Page } from '@playwright/test';
import { seededRandom } from '../../src/math/seededRandom';
import { expect, goHash, hashState, lessonFolders, settled, test } from './fixtures';

const slugs = lessonFolders();

/**
 * A number gone wrong in the page's text: NaN, Infinity, or a JavaScript
 * undefined in a value's place (the word in a sentence, "N is undefined", is
 * the lesson speaking).
 */
const BROKEN = /\bNaN\b|Infinity|[=(,]\s*undefined\b(?!\s*\()|\bundefined\s*[,)=]|^undefined$/m;

const EVENTS = process.env.FUZZ === 'full' ? 400 : 30;

const KEYS = [
  'PageDown',
  'PageDown',
  'PageUp',
  'Home',
  'End',
  'ArrowRight',
  'ArrowLeft',
  '0',
  '+',
  '-',
  '[',
  ']',
  '{',
  '}',
  'Control+z',
  'Control+y',
  'Delete',
];

/** Canvases' pixels, fitted, with no hover or focus ring: the picture of the state. */
async function picture(page: Page): Promise<string[]> {
  await page.mouse.move(1, 1);
  await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
  await page.keyboard.press('0');
  await settled(page);
  return page.locator('canvas[data-figure]').evaluateAll((canvases) =>
    // The figures on screen: a scene's hidden figures are not drawn, so a
    // page that showed them earlier keeps their old pixels out of sight.
    canvases
      .filter((c) => c.checkVisibility())
      .map((c) => `${(c as HTMLElement).dataset.figure}: ${(c as HTMLCanvasElement).toDataURL()}`),
  );
}

const fields = (page: Page) =>
  Object.fromEntries(Object.entries(hashState(page)).filter(([k]) => !k.startsWith('view.')));

/** Two frames drawn. */
const nextFrame = (page: Page) =>
  page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

/**
 * Collects each frame over 50 ms with its parts (measured just before it, each
 * figure's too), to say where its time went.
 */
async function watchLongFrames(page: Page): Promise<void> {
  await page.evaluate(() => {
    const store = window as unknown as { longFrames: string[]; frames: number };
    store.longFrames = [];
    store.frames = 0;
    let parts: [string, number][] = [];
    new PerformanceObserver((list) => {
      // In the order they ended, a frame's parts before the frame: the last
      // part ends with it, and started later.
      const entries = list.getEntries().sort((a, b) => {
        const ends = a.startTime + a.duration - (b.startTime + b.duration);
        return Math.abs(ends) > 1e-3 ? ends : b.startTime - a.startTime;
      });
      for (const entry of entries) {
        const part = /^spline-lab:frame:(.+)$/.exec(entry.name);
        if (part) parts.push([part[1], Math.round(entry.duration)]);
        if (entry.name !== 'spline-lab:frame') continue;
        store.frames++;
        if (entry.duration > 50)
          store.longFrames.push(
            `${Math.round(entry.duration)} ms (${parts.map(([k, v]) => `${k} ${v}`).join(', ')})`,
          );
        parts = [];
      }
    }).observe({ type: 'measure' });
  });
}

/** The long frames seen since the last look (after checking that frames were measured at all). */
async function longFrames(page: Page): Promise<string[]> {
  const { frames, long } = await page.evaluate(() => {
    const store = window as unknown as { longFrames: string[]; frames: number };
    const seen = { frames: store.frames, long: store.longFrames };
    store.longFrames = [];
    return seen;
  });
  expect(frames, 'frames measured').toBeGreaterThan(0);
  return long;
}

/** Opens the preset with the most movable points (the busiest figure). */
async function openBusiestPreset(page: Page): Promise<void> {
  const presets = page.locator('[data-scene]');
  let best = -1;
  let most = -1;
  for (let i = 0; i < (await presets.count()); i++) {
    await presets.nth(i).click();
    await nextFrame(page);
    const handles = await page.locator('.handle-proxy').count();
    if (handles > most) [best, most] = [i, handles];
  }
  if (best >= 0) await presets.nth(best).click();
  await settled(page);
}

/** The link with the last point of its first list of 2D points a million units away (or null). */
function farLink(hash: string): string | null {
  const far = hash.replace(
    /=(-?[\d.]+,-?[\d.]+(?:;-?[\d.]+,-?[\d.]+)+)(?=&|$)/,
    (_, list: string) => {
      const points = list.split(';');
      points[points.length - 1] = '1000000,-1000000';
      return `=${points.join(';')}`;
    },
  );
  return far === hash ? null : far;
}

for (const [index, slug] of slugs.entries()) {
  test(`${slug}: zooming, ${EVENTS} random events and a point a million away leave no error, no long frame, no broken number, and a faithful link`, async ({
    page,
    context,
  }) => {
    test.setTimeout(120_000);
    const rand = seededRandom(0xbeef + index);
    const pick = <T>(list: readonly T[]): T => list[Math.floor(rand() * list.length)];
    await page.goto(`./#/${slug}`);
    await settled(page);
    await openBusiestPreset(page);
    await watchLongFrames(page);

    // 40 notches in and out on the busiest figure, five to a wheel event (a
    // fast flick), a frame drawn after each.
    const figure = page
      .locator('.figure-geometry canvas[data-figure], .figure-space canvas[data-figure]')
      .first();
    const area = (await figure.count()) ? await figure.boundingBox() : null;
    if (area) {
      await page.mouse.move(area.x + area.width / 2, area.y + area.height / 2);
      for (const direction of [-1, 1])
        for (let flick = 0; flick < 8; flick++) {
          await page.mouse.wheel(0, direction * 600);
          await nextFrame(page);
        }
      expect(await longFrames(page), `${slug}: frames over 50 ms while zooming`).toEqual([]);
    }

    const canvases = page.locator('canvas[data-figure]');
    const controls = page.locator(
      '.lesson-page .panel button:visible, .lesson-page .panel input:visible, .lesson-page .controls button:visible, .lesson-page .controls input:visible',
    );
    for (let i = 0; i < EVENTS; i++) {
      const what = rand();
      if (what < 0.3) {
        const canvas = canvases.nth(Math.floor(rand() * (await canvases.count())));
        const box = await canvas.boundingBox();
        if (!box) continue;
        const x = box.x + rand() * box.width;
        const y = box.y + rand() * box.height;
        await page.mouse.move(x, y);
        await page.mouse.down();
        for (let k = 1; k <= 4; k++)
          await page.mouse.move(x + (rand() - 0.5) * 80 * k, y + (rand() - 0.5) * 80 * k);
        await page.mouse.up();
      } else if (what < 0.45) {
        const box = await canvases.first().boundingBox();
        if (!box) continue;
        await page.mouse.move(box.x + rand() * box.width, box.y + rand() * box.height);
        const direction = rand() < 0.5 ? -1 : 1;
        for (let k = 0; k < 8; k++) await page.mouse.wheel(0, direction * 600);
      } else if (what < 0.75) {
        await page.keyboard.press(pick(KEYS));
      } else {
        const count = await controls.count();
        if (count === 0) continue;
        const control = controls.nth(Math.floor(rand() * count));
        const label =
          (await control.getAttribute('aria-label')) ?? (await control.innerText().catch(() => ''));
        // Downloads and the clipboard are tested on their own.
        if (/PNG|SVG|Copy link/.test(label)) continue;
        const type = await control.getAttribute('type');
        if (type === 'range' || type === 'number') {
          await control.evaluate((el, r) => {
            const input = el as HTMLInputElement;
            const min = Number(input.min || 0);
            const max = Number(input.max || 1);
            input.value = String(min + r * (max - min));
            input.dispatchEvent(
              new Event(input.type === 'range' ? 'input' : 'change', { bubbles: true }),
            );
          }, rand());
        } else await control.click({ timeout: 2000 }).catch(() => undefined);
      }
    }
    // Play may be on: pause it, so the state is final.
    const pause = page.getByRole('button', { name: 'Pause' });
    if (await pause.isVisible()) await pause.click();
    await settled(page);

    expect(await longFrames(page), `${slug}: frames over 50 ms`).toEqual([]);
    const text = await page.locator('.lesson-page').innerText();
    expect(text, `${slug}: no broken numbers`).not.toMatch(BROKEN);

    // The state round-trips through its link: same state, and fitted, the same picture.
    const state = fields(page);
    const before = await picture(page);
    const hash = new URL(page.url()).hash;
    const other = await context.newPage();
    await other.setViewportSize(page.viewportSize()!);
    await other.goto(`./${hash}`);
    await settled(other);
    expect(fields(other)).toEqual(state);
    expect(await picture(other), `${slug}: the link shows the same picture`).toEqual(before);
    await other.close();

    // A point a million units away, by a link, on a figure zoomed far in: the
    // kept view must not make the far point expensive to draw.
    const far = farLink(new URL(page.url()).hash);
    if (far !== null) {
      if (area) {
        await page.mouse.move(area.x + area.width / 2, area.y + area.height / 2);
        for (let flick = 0; flick < 6; flick++) await page.mouse.wheel(0, -600);
      }
      await settled(page);
      await longFrames(page);
      await goHash(page, far);
      await expect.poll(() => new URL(page.url()).hash).toContain('1000000');
      await settled(page);
      await nextFrame(page);
      expect(
        await longFrames(page),
        `${slug}: frames over 50 ms with a point a million away`,
      ).toEqual([]);
    }
  });
}
