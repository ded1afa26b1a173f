import { readFileSync } from 'node:fs';
import { expect, snapshot, test } from './fixtures';

test('the gallery lists the lessons by chapter and opens one', async ({ page }) => {
  await page.goto('./');
  await expect(page.getByRole('heading', { name: 'Spline Lab', level: 1 })).toBeVisible();
  await expect(page.getByRole('heading', { name: 'Bézier curves' })).toBeVisible();
  const card = page.getByRole('link', { name: /The de Casteljau construction/ });
  await expect(card).toBeVisible();
  // The thumbnails have loaded before the picture is taken.
  await expect
    .poll(() =>
      page
        .locator('img.thumb')
        .evaluateAll((imgs) => imgs.every((i) => (i as HTMLImageElement).complete)),
    )
    .toBe(true);
  await snapshot(page, 'gallery');
  await card.click();
  await expect(page).toHaveURL(/#\/de-casteljau/);
  await expect(
    page.getByRole('heading', { name: 'The de Casteljau construction', level: 1 }),
  ).toBeVisible();
  // Back returns to the gallery, forward to the lesson.
  await page.goBack();
  await expect(page.getByRole('heading', { name: 'Spline Lab', level: 1 })).toBeVisible();
  await page.goForward();
  await expect(
    page.getByRole('heading', { name: 'The de Casteljau construction', level: 1 }),
  ).toBeVisible();
});

test('an unknown lesson shows the gallery with a notice', async ({ page }) => {
  await page.goto('./#/no-such-lesson');
  await expect(
    page.getByRole('status').getByText(/There is no lesson called “no-such-lesson”/),
  ).toBeVisible();
  await expect(page.getByRole('link', { name: /The de Casteljau construction/ })).toBeVisible();
});

test('presenter view and the dark theme toggle by key and by button', async ({ page }) => {
  await page.goto('./#/de-casteljau');
  const root = page.locator('html');
  await expect(root).not.toHaveClass(/projector/);
  await page.getByRole('button', { name: 'Presenter' }).click();
  await expect(root).toHaveClass(/projector/);
  // The app's top bar gives way to the figure; the presenter's own bar leads out.
  await expect(page.getByRole('button', { name: 'Presenter' })).toBeHidden();
  await snapshot(page, 'de-casteljau-presenter');
  await page.keyboard.press('d');
  await expect(root).toHaveAttribute('data-theme', 'dark');
  await snapshot(page, 'de-casteljau-presenter-dark');
  await page.keyboard.press('d');
  await expect(root).toHaveAttribute('data-theme', 'light');
  // The presenter's tools are off the projected picture until M (or the corner ☰).
  await page.getByRole('button', { name: "Lecturer's controls" }).click();
  await page
    .getByRole('toolbar', { name: 'Presenter tools' })
    .getByRole('button', { name: 'Exit' })
    .click();
  await expect(root).not.toHaveClass(/projector/);
  await page.getByRole('button', { name: 'Dark' }).click();
  await expect(root).toHaveAttribute('data-theme', 'dark');
  await page.getByRole('button', { name: 'Dark' }).click();
  // The setting is kept across a reload.
  await page.keyboard.press('p');
  await page.reload();
  await expect(root).toHaveClass(/projector/);
});

test('the key help opens with ? and closes with Escape', async ({ page }) => {
  await page.goto('./#/de-casteljau');
  await page.keyboard.press('?');
  const dialog = page.getByRole('dialog', { name: 'Help' });
  await expect(dialog).toBeVisible();
  await expect(dialog.getByText(/^Presenter view: the figure/)).toBeVisible();
  await page.keyboard.press('Escape');
  await expect(dialog).toBeHidden();
});

test('PNG and SVG export produce real files of the figure', async ({ page }) => {
  // The whole construction (the lesson opens at step 0).
  await page.goto('./#/de-casteljau?step=5');
  const [png] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'PNG' }).click(),
  ]);
  expect(png.suggestedFilename()).toBe('spline-lab-de-casteljau.png');
  const pngBytes = readFileSync((await png.path())!);
  expect([...pngBytes.subarray(1, 4)].map((b) => String.fromCharCode(b)).join('')).toBe('PNG');
  expect(pngBytes.length).toBeGreaterThan(5000);
  // The grid lies under the figure's canvas on the page; the PNG has it too
  // (light theme: grid #eceef3, drawn on whole pixels at scale 1).
  const gridPixels = await page.evaluate(async (base64) => {
    const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const image = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
    const canvas = new OffscreenCanvas(image.width, image.height);
    const c = canvas.getContext('2d')!;
    c.drawImage(image, 0, 0);
    const data = c.getImageData(0, 0, image.width, image.height).data;
    let n = 0;
    for (let i = 0; i < data.length; i += 4)
      if (data[i] === 0xec && data[i + 1] === 0xee && data[i + 2] === 0xf3) n++;
    return n;
  }, pngBytes.toString('base64'));
  expect(gridPixels).toBeGreaterThan(2000);

  const [svg] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'SVG' }).click(),
  ]);
  expect(svg.suggestedFilename()).toBe('spline-lab-de-casteljau.svg');
  const text = readFileSync((await svg.path())!, 'utf8');
  expect(text.startsWith('<svg xmlns="http://www.w3.org/2000/svg"')).toBe(true);
  // Vector paths and the lecture's labels, not a bitmap.
  expect(text).not.toContain('<image');
  expect((text.match(/<path /g) ?? []).length).toBeGreaterThan(10);
  expect(text).toContain('>P</text>');
});

test('the built app is served with a Content-Security-Policy against foreign scripts', async ({
  page,
}) => {
  await page.goto('./');
  const csp = await page
    .locator('meta[http-equiv="Content-Security-Policy"]')
    .getAttribute('content');
  expect(csp).toContain("script-src 'self'");
  expect(csp).toContain("default-src 'self'");
});

test('the canvas is sharp on a high-density screen', async ({ browser }) => {
  const context = await browser.newContext({
    deviceScaleFactor: 2,
    viewport: { width: 1000, height: 700 },
  });
  const page = await context.newPage();
  await page.goto('./#/de-casteljau');
  const canvas = page.locator('canvas[data-figure="construction"]');
  await expect(canvas).toBeVisible();
  await expect
    .poll(() =>
      canvas.evaluate((c: HTMLCanvasElement) => c.width / c.getBoundingClientRect().width),
    )
    .toBeCloseTo(2, 2);
  // Resizing the window resizes the drawing buffer with it.
  const before = await canvas.evaluate((c: HTMLCanvasElement) => c.width);
  await page.setViewportSize({ width: 1300, height: 700 });
  await expect
    .poll(() => canvas.evaluate((c: HTMLCanvasElement) => c.width))
    .toBeGreaterThan(before);
  await context.close();
});
