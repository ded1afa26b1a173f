/**
 * The parameter's letter is the reader's: chosen at the top of the page, kept
 * on the device and in the link, and every word, formula and figure label of
 * the page follows it. What is read here is the page itself: its text nodes,
 * its typeset formulas' TeX, its figure labels and its controls' names.
 */
import type { Page } from '@playwright/test';
import { expect, lessonFolders, settled, test } from './fixtures';

/**
 * Everything the page shows as text, apart from what quotes the notes (the
 * symbol key's right column, an aside's quotation) and what the reader typed:
 * visible text, the TeX of each typeset formula, names of controls, and the
 * figures' labels as drawn.
 */
async function shownText(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const quoted = '.notes-key dd, [data-notation="own"], textarea, input';
    const main = document.querySelector('main')!;
    const texts: string[] = [];
    const walker = document.createTreeWalker(main, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      const parent = n.parentElement!;
      if (parent.closest(quoted) || parent.closest('.katex')) continue;
      if (parent.closest('[hidden]') || !parent.checkVisibility()) continue;
      if (n.nodeValue!.trim()) texts.push(n.nodeValue!);
    }
    for (const tex of main.querySelectorAll('.katex annotation'))
      if (!tex.closest(quoted)) texts.push(tex.textContent!);
    for (const named of main.querySelectorAll('[aria-label]'))
      texts.push(named.getAttribute('aria-label')!);
    const lab = (window as unknown as { splineLab: { labels(): { labels: { text: string }[] }[] } })
      .splineLab;
    for (const figure of lab.labels()) for (const label of figure.labels) texts.push(label.text);
    return texts;
  });
}

/** Opens a lesson and lists its scenes' ids, in teaching order. */
async function openScenes(page: Page, slug: string): Promise<string[]> {
  await page.goto(`./#/${slug}`);
  await settled(page);
  return page
    .locator('button[data-scene]')
    .evaluateAll((buttons) => buttons.map((b) => b.getAttribute('data-scene')!));
}

/** The texts that write μ, \mu, or a lone t as a symbol (not inside a word). */
const writesMu = (texts: string[]) => texts.filter((t) => /μ|\\mu/.test(t));
const writesT = (texts: string[]) =>
  texts.filter((t) =>
    /(?<![\p{L}\p{N}'’\\_{])t(?![\p{L}'’}])/u.test(t.replace(/\\[a-zA-Z]+/g, '')),
  );

test('the letter chosen at the top follows into the slider, the caption, the formulas, the labels and the link', async ({
  page,
}) => {
  await page.goto('./#/de-casteljau?scene=cubic&step=5');
  await settled(page);
  // t, as the practical writes it, until the reader chooses.
  await expect(page.getByRole('slider', { name: 't', exact: true })).toBeVisible();
  expect(writesMu(await shownText(page))).toEqual([]);

  await page.getByRole('combobox', { name: 'Parameter letter' }).selectOption('mu');
  await expect(page.getByRole('slider', { name: 'μ', exact: true })).toBeVisible();
  await settled(page);
  await expect(page).toHaveURL(/#\/de-casteljau\?par=mu&scene=cubic&/);
  const texts = await shownText(page);
  expect(writesT(texts)).toEqual([]);
  // The formula of step 6 is typeset with \mu, and the figure's point is P(μ).
  expect(texts.some((t) => /\\mu/.test(t))).toBe(true);
  expect(texts.filter((t) => t.includes('P(μ)')).length).toBeGreaterThan(0);

  // Kept on the device: the bare lesson opens in μ again.
  await page.goto('./#/de-casteljau');
  await settled(page);
  await expect(page.getByRole('slider', { name: 'μ', exact: true })).toBeVisible();
});

test('a link with the slides’ letter opens in it, and a letter that is none of the three is said', async ({
  page,
}) => {
  await page.goto('./#/hermite?par=u&scene=one&step=7');
  await settled(page);
  await expect(page.getByRole('slider', { name: 'u', exact: true })).toBeVisible();
  await expect(page.getByRole('combobox', { name: 'Parameter letter' })).toHaveValue('u');
  const texts = await shownText(page);
  expect(writesMu(texts)).toEqual([]);
  expect(writesT(texts)).toEqual([]);

  await page.goto('./#/hermite?par=x&scene=one&step=7');
  await settled(page);
  await expect(page.locator('.notice')).toContainText('par: "x" is not a letter for the parameter');
  // The reader's letter stays as it was.
  await expect(page.getByRole('slider', { name: 'u', exact: true })).toBeVisible();
});

test('a lesson written in μ shows no μ in t, at any step of any scene', async ({ page }) => {
  test.setTimeout(120_000);
  const scenes = await openScenes(page, 'blending');
  expect(scenes.length).toBeGreaterThan(3);
  const found: string[] = [];
  for (const scene of scenes) {
    await page.locator(`button[data-scene="${scene}"]`).click();
    await settled(page);
    await page.keyboard.press('End');
    await settled(page);
    for (const text of writesMu(await shownText(page))) found.push(`${scene}: ${text}`);
  }
  expect(found).toEqual([]);
});

test('every lesson has its key to the notes’ symbols, and a lesson with a parameter leads it with the reader’s letter', async ({
  page,
}) => {
  test.setTimeout(240_000);
  await page.goto('./#/');
  const slugs = await page
    .locator('a[href^="#/"]')
    .evaluateAll((links) =>
      [...new Set(links.map((a) => a.getAttribute('href')!.slice(2)))].filter(
        (s) => s && !s.includes('/') && !s.includes('?'),
      ),
    );
  expect(slugs.length).toBe(12);
  const missing: string[] = [];
  for (const slug of slugs) {
    const scenes = await openScenes(page, slug);
    let found = (await page.locator('details.notes-key').count()) > 0;
    for (const scene of scenes) {
      if (found) break;
      await page.locator(`button[data-scene="${scene}"]`).click();
      await settled(page);
      found = (await page.locator('details.notes-key').count()) > 0;
    }
    if (!found) missing.push(slug);
  }
  expect(missing).toEqual([]);
  // Lagrange writes t; the reader's μ leads its key, with the notes' three letters.
  await page.goto('./#/lagrange?par=mu');
  await settled(page);
  const key = page.locator('details.notes-key').first();
  await key.locator('summary').click();
  await expect(key.locator('dt').first()).toHaveText('μ, the curve’s parameter');
  await expect(key.locator('dd').first()).toContainText(
    'μ in the lecture notes, u in the slides, t in the practical',
  );
});

test('no page writes code for mathematics as plain text (C^(p−1), P_{1}, G_Bez, \\frac), nor P0, PN or N(i,2) in prose, a table or a label, nor a hyphen for a minus sign (-0.65), at the last step of any scene', async ({
  page,
}) => {
  test.setTimeout(240_000);
  const slugs = lessonFolders();
  expect(slugs.length).toBe(12);
  const found: string[] = [];
  for (const slug of slugs) {
    const scenes = await openScenes(page, slug);
    expect(scenes.length, slug).toBeGreaterThan(1);
    for (const scene of scenes) {
      await page.locator(`button[data-scene="${scene}"]`).click();
      await page.keyboard.press('End');
      await settled(page);
      const texts = await page.evaluate(() => {
        // Typeset formulas, and what the reader types or reads as code, are not prose.
        const skip = '.katex, textarea, input, pre, code';
        const main = document.querySelector('main')!;
        const walker = document.createTreeWalker(main, NodeFilter.SHOW_TEXT);
        const texts: { text: string; prose: boolean }[] = [];
        for (let n = walker.nextNode(); n; n = walker.nextNode()) {
          const parent = n.parentElement!;
          if (parent.closest(skip) || parent.closest('[hidden]') || !parent.checkVisibility())
            continue;
          // Prose, tables and a control's label (not a button) name points as
          // the figures do: a radio's "P0 … Pn" reads P₀ … Pₙ, its index a
          // subscript of its own (its accessible name keeps the digits).
          const prose = !!parent.closest('p, li, h2, h3, h4, summary, figcaption, td, th, label');
          if (n.nodeValue!.trim()) texts.push({ text: n.nodeValue!, prose });
        }
        return texts;
      });
      for (const { text, prose } of texts) {
        const code =
          /\^\(|\^\{|_\{|[A-Za-z]_\w|\\[a-zA-Z]{2,}|(?<![\p{L}\d])[CG][0-2](?![\d,])/u.exec(text) ??
          (prose
            ? /(?<![A-Za-z])(?:[PDBQLH]\d|[PD]N(?![\p{L}\d(])|[PDBQLHNux]\([ijkmnrp](?:[+−]\d+)?(?:,[^)]*)?\))/u.exec(
                text,
              )
            : null) ??
          // A negative number is written with a true minus (−0.65), as the figures and formulas write it.
          /(?:^|[\s(=,;:[≤≥<>])-\d/u.exec(text);
        if (code) found.push(`${slug} ${scene}: “${code[0]}” in “${text.slice(0, 90)}”`);
      }
    }
  }
  expect(found).toEqual([]);
});
