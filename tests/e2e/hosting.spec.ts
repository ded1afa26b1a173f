import { createServer, type Server } from 'node:http';
import { readFile } from 'node:fs/promises';
import { extname, join, normalize } from 'node:path';
import { expect, test } from './fixtures';

// These tests are about the service worker (off for the other tests).
test.use({ serviceWorkers: 'allow' });

// dist/ must work from any static host, also below a sub-path.
const PREFIX = '/courses/graphics/spline-lab/';
const TYPES: Record<string, string> = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.svg': 'image/svg+xml',
  '.woff2': 'font/woff2',
  '.woff': 'font/woff',
  '.ttf': 'font/ttf',
};

let server: Server;
let base = '';

test.beforeAll(async () => {
  server = createServer(async (request, response) => {
    const path = new URL(request.url ?? '/', 'http://x').pathname;
    if (!path.startsWith(PREFIX)) {
      response.writeHead(404).end();
      return;
    }
    const file = normalize(join('dist', path.slice(PREFIX.length) || 'index.html'));
    if (!file.startsWith('dist')) {
      response.writeHead(403).end();
      return;
    }
    try {
      const body = await readFile(
        file.endsWith('/') || file === 'dist' ? join(file, 'index.html') : file,
      );
      response
        .writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' })
        .end(body);
    } catch {
      response.writeHead(404).end();
    }
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const address = server.address();
  if (address === null || typeof address === 'string') throw new Error('no port');
  base = `http://127.0.0.1:${address.port}${PREFIX}`;
});

test.afterAll(() => new Promise<void>((resolve) => server.close(() => resolve())));

test('the built app works from a sub-path of a plain static host', async ({ browser }) => {
  const context = await browser.newContext();
  const page = await context.newPage();
  const failed: string[] = [];
  page.on('response', (r) => {
    if (r.status() >= 400) failed.push(r.url());
  });
  await page.goto(`${base}#/de-casteljau`);
  await expect(
    page.getByRole('heading', { name: 'The de Casteljau construction', level: 1 }),
  ).toBeVisible();
  // KaTeX's fonts and styles come from the same sub-path.
  await expect(page.locator('.katex').first()).toBeVisible();
  await page.evaluate(() => document.fonts.ready);
  expect(failed).toEqual([]);
  await context.close();
});

test('once loaded, the app works offline', async ({ page, context }) => {
  // The whole construction, whose last point the check reads (the lesson opens at step 0).
  await page.goto('./#/de-casteljau?step=5');
  // The service worker takes over after the first visit.
  await page.evaluate(async () => {
    await navigator.serviceWorker.ready;
  });
  await page.reload();
  await expect
    .poll(() => page.evaluate(() => navigator.serviceWorker.controller !== null))
    .toBe(true);
  await page.getByRole('heading', { name: 'The de Casteljau construction' }).waitFor();
  await page.evaluate(() => document.fonts.ready);
  await context.setOffline(true);
  await page.reload();
  await expect(
    page.getByRole('heading', { name: 'The de Casteljau construction', level: 1 }),
  ).toBeVisible();
  // P(0.6) of the first scene (Figure 5's t), worked by hand: (2.448, 1.44).
  await expect(page.getByRole('row', { name: /^P₃,₀ / })).toContainText('2.4480');
  await page.goto('./#/');
  await expect(page.getByRole('link', { name: /The de Casteljau construction/ })).toBeVisible();
  await context.setOffline(false);
});

test('after one visit to the gallery, every lesson opens offline with its formula fonts, even with the HTTP cache cleared', async ({
  page,
  context,
  watch,
}) => {
  test.setTimeout(90_000);
  await page.goto('./#/');
  const slugs = await page
    .locator('a.card')
    .evaluateAll((cards) => cards.map((c) => c.getAttribute('data-slug')!));
  expect(slugs.length).toBeGreaterThan(0);
  // The worker stores every file of the build when it installs. `ready` comes
  // when it activates; it controls this page only once its clients.claim() has
  // run, and the lessons below open in this same page (a change of hash), so
  // wait for that too: before it, one run in three fetched a lesson past the
  // worker, offline.
  await page.evaluate(async () => {
    await navigator.serviceWorker.ready;
  });
  await expect
    .poll(() => page.evaluate(() => navigator.serviceWorker.controller !== null))
    .toBe(true);
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.clearBrowserCache');
  await context.setOffline(true);
  for (const slug of slugs) {
    await page.goto(`./#/${slug}`);
    await expect(page.locator('.lesson-page h1')).toBeVisible();
    // Its formulas are typeset (some may sit in a part of the panel not shown now).
    await expect.poll(() => page.locator('.katex').count()).toBeGreaterThan(0);
    const fonts = await page.evaluate(async () => {
      await document.fonts.ready;
      const faces = [...document.fonts];
      return {
        failed: faces.filter((f) => f.status === 'error').map((f) => f.family),
        main: faces.some((f) => f.family === 'KaTeX_Main' && f.status === 'loaded'),
      };
    });
    expect(fonts.failed, `${slug}: fonts that failed offline`).toEqual([]);
    expect(fonts.main, `${slug}: KaTeX_Main loaded offline`).toBe(true);
  }
  // A file the build does not have is an error, not the page.
  const missing = await page.evaluate(async () => {
    const response = await fetch('./assets/no-such-file.js');
    return { status: response.status, type: response.headers.get('content-type') };
  });
  expect(missing.status).toBeGreaterThanOrEqual(400);
  expect(missing.type ?? '').not.toContain('text/html');
  // That one failed load was asked for: it is not an error of the app.
  const expected = watch.errors.findIndex((e) => e.includes('Offline and not stored'));
  expect(expected).toBeGreaterThanOrEqual(0);
  watch.errors.splice(expected, 1);
  await context.setOffline(false);
});
