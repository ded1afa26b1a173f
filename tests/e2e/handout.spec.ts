/**
 * Handouts (issue #21): a lesson printed as the steps the lecturer showed.
 * What the pages must hold is read from the lesson page itself (the clicker
 * walk's captions) and from the notes' numbers, never from the handout's code;
 * the PDF is Chromium's own print output, read with poppler.
 */
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, readdirSync } from 'node:fs';
import type { Page } from '@playwright/test';
import { unzipSync } from 'fflate';
import { expect, settled, test } from './fixtures';

const status = (page: Page) => page.getByText(/^Step \d+\/\d+: /);

/** Every caption of every scene, as a lecturer's clicker walks the lesson page. */
async function walkCaptions(page: Page, slug: string): Promise<Map<string, string[]>> {
  await page.goto(`./#/${slug}`);
  await settled(page);
  const scenes = page.locator('button[data-scene]');
  const ids = await scenes.evaluateAll((buttons) =>
    buttons.map((b) => b.getAttribute('data-scene')!),
  );
  const captions = new Map<string, string[]>();
  for (const id of ids) {
    await page.locator(`button[data-scene="${id}"]`).click();
    await settled(page);
    const list: string[] = [];
    for (;;) {
      const text = (await status(page).first().textContent())!;
      const [, k, last, caption] = /^Step (\d+)\/(\d+): (.*)$/s.exec(text.trim())!;
      expect(Number(k), `${slug} ${id}: one press, one step`).toBe(list.length);
      list.push(caption);
      if (k === last) break;
      await page.keyboard.press('PageDown');
      await settled(page);
    }
    captions.set(id, list);
  }
  return captions;
}

/** Opens the handout from the lesson's own Handout button, as a lecturer would. */
async function openHandout(page: Page): Promise<string> {
  const lessonLink = page.url();
  await page.getByRole('button', { name: 'Handout' }).click();
  await expect(page.locator('.handout[data-ready="true"]')).toBeVisible({ timeout: 20_000 });
  return lessonLink;
}

async function choose(page: Page, group: string, option: string): Promise<void> {
  await page.getByRole('group', { name: group }).getByLabel(option, { exact: true }).check();
  await expect(page.locator('.handout[data-ready="true"]')).toBeVisible({ timeout: 20_000 });
}

const flat = (text: string) => text.replace(/\s+/g, ' ').trim();

/** The PDF as Chromium prints it (print media), its pages' text, and its page count. */
async function printed(page: Page, file: string) {
  await page.emulateMedia({ media: 'print' });
  await page.pdf({ path: file, preferCSSPageSize: true, printBackground: true });
  const info = execFileSync('pdfinfo', [file]).toString();
  const pages = Number(/Pages:\s+(\d+)/.exec(info)![1]);
  const text = (p: number) =>
    flat(execFileSync('pdftotext', ['-f', String(p), '-l', String(p), file, '-']).toString());
  const fonts = execFileSync('pdffonts', [file]).toString();
  return { pages, info, text, fonts };
}

/** Each sheet's frames (scene, step) and whether each frame and table lies inside its sheet, under print media. */
function sheetsUnderPrint(page: Page) {
  return page.evaluate(() =>
    [...document.querySelectorAll('.sheet')].map((sheet) => {
      const box = sheet.getBoundingClientRect();
      const items = [...sheet.querySelectorAll<HTMLElement>('.frame, .handout-table')];
      return {
        top: box.top + window.scrollY,
        height: box.height,
        frames: items
          .filter((f) => f.classList.contains('frame'))
          .map((f) => ({ scene: f.dataset.scene!, step: Number(f.dataset.step) })),
        inside: items.every((item) => {
          const r = item.getBoundingClientRect();
          return (
            r.top >= box.top - 0.5 &&
            r.bottom <= box.bottom + 0.5 &&
            r.left >= box.left - 0.5 &&
            r.right <= box.right + 0.5
          );
        }),
      };
    }),
  );
}

const MM = 96 / 25.4;

/** The PDF's page size in points, within a point of the paper's (Chromium rounds to whole pixels). */
function expectPageSize(info: string, width: number, height: number): void {
  const [, w, h] = /Page size:\s+([\d.]+) x ([\d.]+) pts/.exec(info)!;
  expect(Math.abs(Number(w) - width)).toBeLessThan(1);
  expect(Math.abs(Number(h) - height)).toBeLessThan(1);
}

test.describe('handouts', () => {
  test.setTimeout(120_000);

  test('de Casteljau, every step, 4 a page on A4: the pages, the captions, the formulas and the link', async ({
    page,
  }, testInfo) => {
    const captions = await walkCaptions(page, 'de-casteljau');
    // The lesson's six scenes: 6, 5, 6, 8, 10 and 5 steps (counted on the lesson page above).
    expect([...captions.values()].map((c) => c.length)).toEqual([6, 5, 6, 8, 10, 5]);
    await page.locator('button[data-scene]').first().click();
    await settled(page);
    const lessonLink = await openHandout(page);
    await choose(page, 'Steps', 'Every step');
    // By hand: a page holds 2 × 2 frames; each scene's table of points (10, 6,
    // 10, 21 rows: at most 108 mm, under one 116 mm row of A4's grid) starts a
    // fresh row after the scene's last frame. Cubic: 4 | 2 + table. Quadratic:
    // 4 | 1 + table. Loop: 4 | 2 + table. Degree 5: 4 | 4 | table. Pseudocode:
    // 4 | 4 | 2 + table. Bernstein form: 4 | 1 + table. 14 pages.
    await expect(page.locator('.handout')).toHaveAttribute('data-pages', '14');
    const file = testInfo.outputPath('de-casteljau.pdf');
    const pdf = await printed(page, file);
    expect(pdf.pages).toBe(14);
    expectPageSize(pdf.info, 595.28, 841.89);

    // No frame crosses a page's edge: each sheet is one A4 page, stacked page
    // after page, every frame inside its sheet, and PDF page i holds exactly
    // the captions of sheet i's frames.
    const sheets = await sheetsUnderPrint(page);
    expect(sheets).toHaveLength(14);
    for (const [i, sheet] of sheets.entries()) {
      expect(sheet.height).toBeCloseTo(297 * MM, 0);
      expect(sheet.inside, `page ${i + 1}: every frame inside its sheet`).toBe(true);
      const text = pdf.text(i + 1);
      expect(text).toContain(`Page ${i + 1} of 14`);
      for (const { scene, step } of sheet.frames)
        expect(text, `page ${i + 1}: ${scene} step ${step}`).toContain(
          flat(captions.get(scene)![step]),
        );
    }
    // Every step of every scene is on some page, in the lesson's order.
    expect(sheets.flatMap((s) => s.frames).map((f) => `${f.scene}:${f.step}`)).toEqual(
      [...captions].flatMap(([scene, list]) => list.map((_, k) => `${scene}:${k}`)),
    );

    // Formulas as text in KaTeX's own fonts, not missing glyphs: the cubic's
    // last step says P(0.6) = (2.448, 1.440) (Figure 5's t), worked by hand
    // from the points (0,0), (1,2), (3,2), (4,0): 0.288·(1, 2) + 0.432·(3, 2) + 0.216·(4, 0).
    expect(pdf.fonts).toMatch(/KaTeX_Main/);
    expect(pdf.fonts).toMatch(/KaTeX_Math/);
    const all = Array.from({ length: pdf.pages }, (_, i) => pdf.text(i + 1)).join(' ');
    expect(all).toMatch(/\(\s?2\.448,\s?1\.440\)/);
    expect(all).not.toMatch(/\uFFFD/);
    // The table of points under the cubic: P₃,₀ = P(0.6).
    expect(pdf.text(2)).toMatch(/P₃,₀ 2\.4480 1\.4400/);

    // The title block: the lesson's title, and the link to the lesson as shown.
    const first = pdf.text(1);
    expect(first).toContain('The de Casteljau construction');
    // (pdftotext may break the long link across lines.)
    expect(first.replace(/\s/g, '')).toContain(lessonLink);
    await expect(
      page.getByRole('img', { name: 'QR code of the link to this lesson' }),
    ).toBeVisible();

    // The pages as pictures, to look at (listed in the closing note).
    const dir = testInfo.outputPath('pages');
    mkdirSync(dir, { recursive: true });
    execFileSync('pdftoppm', ['-r', '40', '-png', file, `${dir}/page`]);
    expect(readdirSync(dir).filter((f) => f.endsWith('.png'))).toHaveLength(14);
  });

  test('raster, every step, 6 a page on Letter: its pixel grid prints, every caption on its page', async ({
    page,
  }, testInfo) => {
    const captions = await walkCaptions(page, 'raster');
    const frames = [...captions.values()].reduce((n, list) => n + list.length, 0);
    const canvases = await page
      .locator('canvas[data-figure]')
      .evaluateAll((all) => all.map((c) => c.getAttribute('aria-label')));
    expect(canvases).toHaveLength(2);
    await page.locator('button[data-scene]').first().click();
    await settled(page);
    await openHandout(page);
    await choose(page, 'Steps', 'Every step');
    await choose(page, 'Frames a page', '6');
    await choose(page, 'Paper', 'Letter');
    // The options are in the link: the handout opens again as chosen.
    expect(page.url()).toMatch(/handout\.per-page=6/);
    expect(page.url()).toMatch(/handout\.paper=letter/);
    // No tables: frames fill 2 × 3 grids page after page.
    const expected = Math.ceil(frames / 6);
    const pdf = await printed(page, testInfo.outputPath('raster.pdf'));
    expect(pdf.pages).toBe(expected);
    expectPageSize(pdf.info, 612, 792);
    const sheets = await sheetsUnderPrint(page);
    expect(sheets).toHaveLength(expected);
    for (const [i, sheet] of sheets.entries()) {
      expect(sheet.height).toBeCloseTo(279.4 * MM, 0);
      expect(sheet.inside).toBe(true);
      const text = pdf.text(i + 1);
      for (const { scene, step } of sheet.frames)
        expect(text, `page ${i + 1}: ${scene} step ${step}`).toContain(
          flat(captions.get(scene)![step]),
        );
    }
    // Every frame draws the lesson's figures, the curve with its pixels and
    // the side view, named as the lesson page names its canvases.
    const names = await page.evaluate(() =>
      [...document.querySelectorAll('.frame')].map((f) =>
        [...f.querySelectorAll('svg > svg > title')].map((t) => t.textContent),
      ),
    );
    expect(names).toHaveLength(frames);
    for (const shown of names) expect(shown).toEqual(canvases);

    await page.emulateMedia({ media: 'screen' });
    await page.reload();
    await expect(page.locator('.handout[data-ready="true"]')).toBeVisible({ timeout: 20_000 });
    await expect(
      page.getByRole('group', { name: 'Frames a page' }).getByLabel('6', { exact: true }),
    ).toBeChecked();
    await expect(page.locator('.handout')).toHaveAttribute('data-pages', String(expected));
  });

  test('each scene’s last step only, and the frames as SVG files in a zip', async ({ page }) => {
    await page.goto('./#/quadratic');
    await settled(page);
    const scenes = await page.locator('button[data-scene]').count();
    await openHandout(page);
    await choose(page, 'Steps', 'Each scene’s last step');
    await expect(page.locator('.frame')).toHaveCount(scenes);
    const download = page.waitForEvent('download');
    await page.getByRole('button', { name: 'Frames as SVG (.zip)' }).click();
    const zip = unzipSync(readFileSync((await (await download).path())!));
    const names = Object.keys(zip);
    expect(names).toHaveLength(scenes);
    for (const name of names) {
      expect(name).toMatch(/^\d\d-[a-z0-9-]+-step-\d\d\.svg$/);
      expect(new TextDecoder().decode(zip[name])).toMatch(
        /^<svg xmlns="http:\/\/www\.w3\.org\/2000\/svg"/,
      );
    }
  });

  test('the 3D patch is printed from the camera the lecturer turned to', async ({ page }) => {
    const firstFrame = () =>
      page
        .locator('.frame svg')
        .first()
        .evaluate((svg) => new XMLSerializer().serializeToString(svg));
    // The patch scene's first step from the lesson's own camera.
    await page.goto('./#/surface/handout?scene=patch&handout.scenes=patch');
    await expect(page.locator('.handout[data-ready="true"]')).toBeVisible({ timeout: 20_000 });
    const before = await firstFrame();
    await page.goto('./#/surface');
    await settled(page);
    const canvas = page.locator('canvas[data-figure="patch"]');
    const box = (await canvas.boundingBox())!;
    // Turn the camera by dragging empty space at the figure's edge.
    await page.mouse.move(box.x + 12, box.y + box.height - 12);
    await page.mouse.down();
    await page.mouse.move(box.x + 160, box.y + box.height - 40, { steps: 8 });
    await page.mouse.up();
    await settled(page);
    expect(page.url()).toMatch(/view\.patch=/);
    await openHandout(page);
    expect(page.url()).toMatch(/\/handout\?.*view\.patch=/);
    expect(await firstFrame()).not.toBe(before);
  });

  test('a broken handout option says so and prints the defaults', async ({ page }) => {
    await page.goto('./#/hermite/handout?handout.per-page=5&handout.paper=a3');
    await expect(page.locator('.handout[data-ready="true"]')).toBeVisible({ timeout: 20_000 });
    await expect(page.getByText(/5 frames a page is not offered/)).toBeVisible();
    await expect(page.getByText(/Paper “a3” is not A4 or Letter/)).toBeVisible();
    await expect(
      page.getByRole('group', { name: 'Frames a page' }).getByLabel('4', { exact: true }),
    ).toBeChecked();
  });
});
