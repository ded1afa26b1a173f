import type { Locator, Page } from '@playwright/test';
import { expect, expectHash, settled, test, linkState } from './fixtures';

const figure = (page: Page) => page.locator('canvas[data-figure="construction"]');

async function centre(locator: Locator): Promise<[number, number]> {
  const box = (await locator.boundingBox())!;
  return [box.x + box.width / 2, box.y + box.height / 2];
}

/**
 * A gesture as a finger or a pen makes it, sent through Chromium's own input
 * pipeline (DevTools protocol), so the page sees real touch/pen pointer events.
 */
async function gesture(page: Page, type: 'touch' | 'pen', path: [number, number][], holdMs = 0) {
  const cdp = await page.context().newCDPSession(page);
  const [first, ...rest] = path;
  const last = path[path.length - 1];
  if (type === 'touch') {
    const touch = (t: 'touchStart' | 'touchMove' | 'touchEnd', [x, y]: [number, number]) =>
      cdp.send('Input.dispatchTouchEvent', {
        type: t,
        touchPoints: t === 'touchEnd' ? [] : [{ x, y }],
      });
    await touch('touchStart', first);
    if (holdMs) await page.waitForTimeout(holdMs);
    for (const point of rest) await touch('touchMove', point);
    await touch('touchEnd', last);
  } else {
    const pen = (
      t: 'mousePressed' | 'mouseMoved' | 'mouseReleased',
      [x, y]: [number, number],
      buttons: number,
    ) =>
      cdp.send('Input.dispatchMouseEvent', {
        type: t,
        x,
        y,
        button: 'left',
        buttons,
        clickCount: 1,
        pointerType: 'pen',
      });
    await pen('mousePressed', first, 1);
    if (holdMs) await page.waitForTimeout(holdMs);
    for (const point of rest) await pen('mouseMoved', point, 1);
    await pen('mouseReleased', last, 0);
  }
  await cdp.detach();
}

test.beforeEach(async ({ page }) => {
  await page.goto('./#/de-casteljau');
  await expect(figure(page)).toBeVisible();
  await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
});

for (const type of ['touch', 'pen'] as const) {
  test(`a ${type} drags a point, with a finger-sized reach`, async ({ page }) => {
    const [x, y] = await centre(page.getByRole('button', { name: /^P1 at/ }));
    // Land 24 px off the point: beyond a mouse's reach (handle radius 8 + 10 px),
    // within a finger's or a pen's (8 + 22 px).
    await gesture(page, type, [
      [x + 24, y],
      [x + 44, y + 20],
      [x + 64, y + 40],
    ]);
    await expectHash(page, 'p', (v) => v.split(';')[1] !== '1,2');
    const [px, py] = (await linkState(page)).p.split(';')[1].split(',').map(Number);
    expect(px).toBeGreaterThan(1);
    expect(py).toBeLessThan(2);
  });
}

test('a mouse 24 px from a point pans instead of grabbing it', async ({ page }) => {
  const p1 = page.getByRole('button', { name: /^P1 at/ });
  const [x, y] = await centre(p1);
  await page.mouse.move(x + 24, y);
  await page.mouse.down();
  await page.mouse.move(x + 64, y + 40, { steps: 4 });
  await page.mouse.up();
  await expect.poll(async () => (await centre(p1))[0]).toBeCloseTo(x + 40, 0);
  expect((await linkState(page)).p).toBe('0,0;1,2;3,2;4,0');
});

test('a long press on empty space adds a point; a short one does not', async ({ page }) => {
  const box = (await figure(page).boundingBox())!;
  const spot: [number, number] = [box.x + box.width / 2, box.y + box.height - 40];
  await gesture(page, 'touch', [spot], 100);
  await gesture(page, 'touch', [spot], 800);
  // The long press added one point; had the short one added one too, there would be six.
  await expectHash(page, 'p', (v) => v.split(';').length >= 5);
  await settled(page);
  expect((await linkState(page)).p.split(';')).toHaveLength(5);
});

test('dragging empty space pans the view and the wheel zooms it, without touching the state', async ({
  page,
}) => {
  const p1 = page.getByRole('button', { name: /^P1 at/ });
  const [x0, y0] = await centre(p1);
  const box = (await figure(page).boundingBox())!;
  await page.mouse.move(box.x + 30, box.y + 30);
  await page.mouse.down();
  await page.mouse.move(box.x + 130, box.y + 80, { steps: 4 });
  await page.mouse.up();
  await expect.poll(async () => (await centre(p1))[0]).toBeCloseTo(x0 + 100, 0);
  const [x1, y1] = await centre(p1);
  expect(y1).toBeCloseTo(y0 + 50, 0);
  await page.mouse.move(x1, y1);
  await page.mouse.wheel(0, -400);
  // Zooming about the pointer keeps the point under it.
  await expect
    .poll(async () => Math.hypot(...(await centre(p1)).map((v, i) => v - [x1, y1][i])))
    .toBeLessThan(2);
  const p2 = page.getByRole('button', { name: /^P2 at/ });
  const before = await centre(p2);
  await page.keyboard.press('0');
  await expect.poll(async () => (await centre(p2))[0]).not.toBeCloseTo(before[0], 0);
  expect((await linkState(page)).p).toBe('0,0;1,2;3,2;4,0');
});

test('two fingers pinch to zoom the figure', async ({ page }) => {
  const p0 = page.getByRole('button', { name: /^P0 at/ });
  const p3 = page.getByRole('button', { name: /^P3 at/ });
  const span = async () => (await centre(p3))[0] - (await centre(p0))[0];
  const before = await span();
  const box = (await figure(page).boundingBox())!;
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  const cdp = await page.context().newCDPSession(page);
  const fingers = (type: 'touchStart' | 'touchMove' | 'touchEnd', d: number) =>
    cdp.send('Input.dispatchTouchEvent', {
      type,
      touchPoints:
        type === 'touchEnd'
          ? []
          : [
              { x: cx - d, y: cy, id: 1 },
              { x: cx + d, y: cy, id: 2 },
            ],
    });
  await fingers('touchStart', 40);
  for (const d of [50, 60, 70, 80]) await fingers('touchMove', d);
  await fingers('touchEnd', 80);
  await cdp.detach();
  // Fingers twice as far apart: the figure twice as large.
  await expect.poll(span).toBeCloseTo(before * 2, -1);
  expect((await linkState(page)).p).toBe('0,0;1,2;3,2;4,0');
});

test('moving a point by keyboard is announced to screen readers', async ({ page }) => {
  await page.getByRole('button', { name: /^P3 at/ }).focus();
  await page.keyboard.press('ArrowLeft');
  await settled(page);
  // One key step left: x a little under 4 (the step follows the zoom), y kept.
  const [x, y] = (await linkState(page)).p.split(';')[3].split(',').map(Number);
  expect(x).toBeLessThan(4);
  expect(x).toBeGreaterThan(3.4);
  expect(y).toBe(0);
  const name = `P3 at (${x.toFixed(2)}, 0.00)`;
  await expect(page.locator('[data-announcer]')).toHaveText(name);
  await expect(page.getByRole('button', { name })).toBeFocused();
});

test('Play animates t and respects reduced motion with calm jumps', async ({ page }) => {
  await page.getByRole('button', { name: 'Play' }).click();
  await expectHash(page, 't', (v) => v !== '0.4');
  await page.getByRole('button', { name: 'Pause' }).click();
  await settled(page);
  // Calm jumps of a tenth of the range from 0.4, not a continuous glide.
  const t = Number((await linkState(page)).t);
  const jumps = (t < 0.4 ? t + 1 - 0.4 : t - 0.4) / 0.1;
  expect(Math.abs(jumps - Math.round(jumps))).toBeLessThan(1e-9);
  // Paused: a jump's time later, t has not moved.
  await page.waitForTimeout(1100);
  expect(Number((await linkState(page)).t)).toBe(t);
});

test.describe('with motion allowed', () => {
  test.use({ reducedMotion: 'no-preference' });

  /** The parameter the slider shows on each of the next `frames` animation frames, with the frame's time. */
  const sample = (page: Page, frames: number) =>
    page.evaluate(
      (count) =>
        new Promise<[number, number][]>((resolve) => {
          const slider = document.querySelector<HTMLInputElement>('.controls input[type=range]')!;
          const seen: [number, number][] = [];
          const frame = (now: number) => {
            // Its spoken value has three decimals (the slider's own value snaps to its step).
            seen.push([now, Number(slider.getAttribute('aria-valuetext')!.split('=')[1])]);
            if (seen.length < count) requestAnimationFrame(frame);
            else resolve(seen);
          };
          requestAnimationFrame(frame);
        }),
      frames,
    );

  /**
   * Parameter per second of play over the samples (a wrap from 1 back to 0 is
   * not a step back). Play counts at most 0.1 s for one frame, so a frame the
   * machine made late is counted as Play counts it.
   */
  const rate = (seen: [number, number][]) => {
    let moved = 0;
    let seconds = 0;
    for (let i = 1; i < seen.length; i++) {
      const step = seen[i][1] - seen[i - 1][1];
      moved += step < -0.5 ? step + 1 : step;
      seconds += Math.min(0.1, (seen[i][0] - seen[i - 1][0]) / 1000);
    }
    return moved / seconds;
  };

  test('Play glides t continuously, one sweep in five seconds, and the speed key doubles it', async ({
    page,
  }) => {
    await page.getByRole('button', { name: 'Play' }).click();
    const seen = await sample(page, 40);
    const values = new Set(seen.map(([, t]) => t));
    // A glide: a new value on most frames, each a small step (no calm jumps of 0.1).
    expect(values.size).toBeGreaterThan(25);
    for (let i = 1; i < seen.length; i++) {
      const step = seen[i][1] - seen[i - 1][1];
      expect(step < -0.5 ? step + 1 : step).toBeLessThan(0.05);
    }
    // 1×: the range [0, 1] in 5 s is 0.2 per second; 2× is 0.4.
    const normal = rate(seen);
    expect(normal).toBeGreaterThan(0.17);
    expect(normal).toBeLessThan(0.23);
    await page.keyboard.press('>');
    await expect(page.getByRole('button', { name: 'Speed 2×' })).toBeVisible();
    const fast = rate(await sample(page, 40));
    expect(fast).toBeGreaterThan(0.34);
    expect(fast).toBeLessThan(0.46);
    // Pause: the state is final and in the link, and stays.
    await page.getByRole('button', { name: 'Pause' }).click();
    await settled(page);
    const t = Number((await linkState(page)).t);
    const after = await sample(page, 10);
    expect(after.every(([, v]) => v === after[0][1])).toBe(true);
    expect(Math.abs(after[0][1] - t)).toBeLessThanOrEqual(0.0005 + 1e-12);
  });

  test('Play from the start of the range stays in range when the first frame is stamped before the press', async ({
    page,
  }) => {
    // Chromium may stamp the first animation frame before the click that
    // started Play: the first step is then negative. Make every frame so.
    await page.addInitScript(() => {
      const request = window.requestAnimationFrame.bind(window);
      window.requestAnimationFrame = (callback) => request((now) => callback(now - 40));
    });
    for (const [link, key, min] of [
      ['#/blending?mu=0', 'mu', 0],
      ['#/de-casteljau?t=0', 't', 0],
      ['#/hermite?mu=0', 'mu', 0],
      ['#/bezier-properties?t=0', 't', 0],
      ['#/b-splines?t=0', 't', 0],
    ] as const) {
      await page.goto(`./${link}`);
      await page.getByRole('button', { name: 'Play' }).click();
      // It moves on from the start (a thrown basis at t < 0 fails the test's watch).
      const slider = page.locator('.controls input[type=range]');
      await expect
        .poll(async () => Number((await slider.getAttribute('aria-valuetext'))!.split('=')[1]))
        .toBeGreaterThan(min);
      await page.getByRole('button', { name: 'Pause' }).click();
      await settled(page);
      expect(Number((await linkState(page))[key]), link).toBeGreaterThanOrEqual(min);
    }
  });
});
