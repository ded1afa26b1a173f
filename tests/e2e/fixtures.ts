import { test as base, expect, type Page } from '@playwright/test';
import { existsSync, mkdirSync, readdirSync, readFileSync } from 'node:fs';

/**
 * Every browser test runs under watch: a console error, an uncaught exception
 * or a request to anywhere but the page's own origin fails it.
 */
export const test = base.extend<{ watch: { errors: string[]; foreign: string[] } }>({
  watch: [
    async ({ page, baseURL }, use) => {
      const errors: string[] = [];
      const foreign: string[] = [];
      const origin = new URL(baseURL ?? 'http://127.0.0.1').origin;
      page.on('console', (message) => {
        if (message.type() === 'error') errors.push(message.text());
      });
      page.on('pageerror', (error) => errors.push(`uncaught: ${error.message}`));
      page.on('request', (request) => {
        const url = request.url();
        if (/^(data|blob):/.test(url)) return;
        if (new URL(url).origin !== origin) foreign.push(url);
      });
      await use({ errors, foreign });
      expect(errors, 'console errors').toEqual([]);
      expect(foreign, 'requests outside the origin').toEqual([]);
    },
    { auto: true },
  ],
});

export { expect };

/**
 * A number as the page writes it, read back: a true minus sign (−0.65, as the
 * figures, formulas and tables write it) reads as JavaScript's minus.
 */
export const readNumber = (text: string | null): number =>
  Number((text ?? '').trim().replace(/\u2212/g, '-'));

/**
 * Saves a screenshot to look at, under artifacts/screenshots/, when the run
 * asks for them (`npm run screenshots`). `npm test` compares each scene with
 * its reviewed reference instead (pictures.spec.ts); writing these too cost
 * about 0.3 s of CPU each, some 150 of them.
 */
export async function snapshot(page: Page, name: string): Promise<void> {
  if (!process.env.SCREENSHOTS) return;
  mkdirSync('artifacts/screenshots', { recursive: true });
  await page.screenshot({ path: `artifacts/screenshots/${name}.png` });
}

/** The lesson's state from the URL hash, as key → raw value. */
export function hashState(page: Page): Record<string, string> {
  const hash = new URL(page.url()).hash;
  const query = hash.includes('?') ? hash.slice(hash.indexOf('?') + 1) : '';
  return Object.fromEntries(
    query
      .split('&')
      .filter(Boolean)
      .map((part) => part.split('=') as [string, string]),
  );
}

/** Waits until the URL hash carries `key`=`value` (the URL is written shortly after a change). */
export async function expectHash(
  page: Page,
  key: string,
  matcher: (value: string) => boolean,
): Promise<void> {
  await expect.poll(() => matcher(hashState(page)[key] ?? '')).toBe(true);
}

/**
 * Waits until the page has settled after an action: the state is final, its
 * frame drawn, the panel updated and the link written (the app's own signal,
 * instead of sleeping or polling the link).
 */
export async function settled(page: Page): Promise<void> {
  await page.evaluate(() =>
    (window as unknown as { splineLab: { settled(): Promise<void> } }).splineLab.settled(),
  );
}

/**
 * Goes to `hash` (e.g. `#/road?scene=swing&step=6`) as a pasted link does, and
 * returns once the page has applied it (not yet settled: see openHash). The
 * page applies a new hash on its hashchange event, a task of its own: a key
 * pressed or a check made straight after setting the hash could reach the page
 * first and act on the previous link's state (phone.spec's Home then left the
 * road's swing scene at its last step, once in a ×3 run on a busy machine).
 */
export async function goHash(page: Page, hash: string): Promise<void> {
  await page.evaluate(
    (target) =>
      new Promise<void>((resolve) => {
        const before = location.href;
        const lab = window as unknown as LinkClock;
        const given = performance.now();
        // The page's own time from being given the link to having settled on
        // it, taken inside the page (linkSettleTime).
        const settle = (): void => {
          lab.linkSettleMs = lab.splineLab.settled().then(() => performance.now() - given);
          resolve();
        };
        location.hash = target;
        // The same link again fires no hashchange: there is nothing to apply.
        if (location.href === before) settle();
        // After the page's own listener, which applies the link (main.ts).
        else addEventListener('hashchange', settle, { once: true });
      }),
    hash,
  );
}

interface LinkClock {
  splineLab: { settled(): Promise<void> };
  linkSettleMs?: Promise<number>;
}

/**
 * Milliseconds, on the page's own clock, from goHash giving the page its last
 * link to the page having applied it, drawn it and written its panel: the
 * page's time, without the harness's. A fuzzed link of 790,000 characters
 * takes the page 50–170 ms even with every core busy; timed from the test,
 * the link's trips to and from the page through the harness made it over
 * 2 s on a busy machine (3 of 5 full runs).
 */
export const linkSettleTime = (page: Page): Promise<number> =>
  page.evaluate(() => {
    const clock = (window as unknown as LinkClock).linkSettleMs;
    if (!clock) throw new Error('linkSettleTime: no link was given with goHash');
    return clock;
  });

/** goHash, then the page settled: the link's state drawn, its panel written. */
export async function openHash(page: Page, hash: string): Promise<void> {
  await goHash(page, hash);
  await settled(page);
}

/**
 * Every lesson, as the app's registry finds them (a folder with a meta.ts), for
 * generating one test per lesson (no list kept by hand).
 */
export function lessonFolders(): string[] {
  return readdirSync('src/lessons', { withFileTypes: true })
    .filter((d) => d.isDirectory() && existsSync(`src/lessons/${d.name}/meta.ts`))
    .map((d) => d.name);
}

/** Every lesson, as the gallery lists it (no list kept by hand). */
export async function lessonSlugs(page: Page): Promise<string[]> {
  await page.goto('./#/');
  await expect(page.locator('a.card').first()).toBeVisible();
  return page
    .locator('a.card')
    .evaluateAll((cards) => cards.map((c) => c.getAttribute('data-slug')!));
}

/**
 * The lesson's scenes in teaching order, read once the page has settled. Read
 * straight after a load the panel may have no scene buttons yet, and a walk
 * over an empty list passes having checked nothing.
 */
export async function sceneIds(page: Page): Promise<string[]> {
  await settled(page);
  const buttons = page.locator('button[data-scene]');
  await expect(buttons.first()).toBeAttached();
  return buttons.evaluateAll((els) => [
    ...new Set(els.map((e) => (e as HTMLElement).dataset.scene!)),
  ]);
}

/**
 * The state in the link once the page has settled. The link is written
 * shortly after a change: read straight after an action it may still hold the
 * state before it (stop 17's CI failed on exactly that).
 */
export async function linkState(page: Page): Promise<Record<string, string>> {
  await settled(page);
  return hashState(page);
}

/**
 * The lessons whose text follows the lecture notes write the parameter μ:
 * their tests read that text, so they open them in the lecture's letter
 * (chosen as a reader would, kept on the device). Every letter is checked for
 * every step in tests/notation.test.ts, and the setting itself in shell.spec.
 */
export const LECTURE_LETTER_LESSONS: readonly string[] = ['blending', 'hermite', 'quadratic'];

export async function inLecturesLetter(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const key = 'spline-lab:settings';
    let settings: Record<string, unknown> = {};
    try {
      settings = JSON.parse(localStorage.getItem(key) ?? '{}') as Record<string, unknown>;
    } catch {
      settings = {};
    }
    if (!('letter' in settings))
      localStorage.setItem(key, JSON.stringify({ ...settings, letter: 'mu' }));
  });
}

/** Every scene of every lesson, at its first and last step (as tests/links.test.ts keeps them). */
export const sceneLinks = JSON.parse(readFileSync('tests/scene-links.json', 'utf8')) as Record<
  string,
  string[]
>;

/**
 * Opens each of a lesson's scene links in turn (first and last step of every
 * scene), settled, and lets `look` measure it; what it finds is collected.
 */
export async function eachSceneEnd(
  page: Page,
  slug: string,
  look: (where: string) => Promise<string[]>,
): Promise<string[]> {
  const faults: string[] = [];
  const queries = sceneLinks[slug];
  await page.goto(`./#/${slug}?${queries[0]}`);
  for (const query of queries) {
    await openHash(page, `#/${slug}?${query}`);
    faults.push(...(await look(`${slug}?${query}`)));
  }
  return faults;
}

/**
 * Walks every step of every scene of a lesson, as a clicker does: each scene
 * opened at its step 0 (from its links in tests/scene-links.json), then one
 * PageDown at a time to its last step, settled at each, and `look` measures
 * it. A fault in a middle step is found too (the road's derivation formulas
 * were cut at 1366 px on steps 3, 4 and 7, while both ends were whole).
 */
export async function eachStep(
  page: Page,
  slug: string,
  look: (where: string) => Promise<string[]>,
): Promise<string[]> {
  // Each scene's links, by scene (the lesson's first link may name none: its first scene).
  const last = new Map<string, { query: string; step: number }>();
  for (const query of sceneLinks[slug]) {
    const params = new URLSearchParams(query);
    const scene = params.get('scene') ?? '';
    const step = Number(params.get('step') ?? 0);
    if (!last.has(scene) || step > last.get(scene)!.step) last.set(scene, { query, step });
  }
  if (last.has('') && last.size > 1) last.delete('');
  const faults: string[] = [];
  await page.goto(`./#/${slug}?${sceneLinks[slug][0]}`);
  for (const [scene, { query, step: steps }] of last) {
    await openHash(page, `#/${slug}?${query.replace(/step=\d+/, 'step=0')}`);
    for (let k = 0; k <= steps; k++) {
      if (k > 0) {
        await page.keyboard.press('PageDown');
        await settled(page);
      }
      faults.push(...(await look(`${slug} ${scene || 'first scene'} step ${k}`)));
    }
  }
  return faults;
}

/** The sizes of the figures on screen, in CSS pixels, e.g. "main 1280×700, basis 620×700". */
export const figureSizes = (page: Page) =>
  page.locator('canvas[data-figure]').evaluateAll((canvases) =>
    canvases
      .filter((c) => c.checkVisibility())
      .map((c) => {
        const box = c.getBoundingClientRect();
        return `${(c as HTMLElement).dataset.figure} ${Math.round(box.width)}×${Math.round(box.height)}`;
      })
      .join(', '),
  );
