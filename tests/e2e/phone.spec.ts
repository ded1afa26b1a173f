import type { Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { expect, settled, test } from './fixtures';

/** Every scene of every lesson, at its first and last step (as tests/links.test.ts keeps them). */
const links = JSON.parse(readFileSync('tests/scene-links.json', 'utf8')) as Record<
  string,
  string[]
>;

/**
 * A student on a phone, in every scene of every lesson, at its first and
 * last step: the page is no wider than the screen; the figure, Next and the
 * slider are on the first screen together; every control is a 44 px target.
 */
const PHONES = [
  { width: 360, height: 740 },
  { width: 390, height: 844 },
];

/** What a phone shows of one view, measured in the page. */
function measure(page: Page) {
  return page.evaluate(() => {
    window.scrollTo(0, 0);
    const root = document.documentElement;
    const screen = window.innerHeight;
    const onFirstScreen = (el: Element | null) => {
      if (!el) return null;
      const box = el.getBoundingClientRect();
      return box.top >= -0.5 && box.bottom <= screen + 0.5 && box.height > 0;
    };
    const shown = (el: Element) => {
      if (el.closest('[hidden], .visually-hidden, dialog:not([open])')) return false;
      const style = getComputedStyle(el);
      return (
        style.visibility !== 'hidden' && style.display !== 'none' && el.getClientRects().length > 0
      );
    };
    const figure = [...document.querySelectorAll('.figure')].find(shown) ?? null;
    const next = [...document.querySelectorAll('.steps button')].find((b) =>
      /^Next/.test(b.textContent ?? ''),
    );
    const slider = document.querySelector('.controls .param-slider');
    // Tap targets: what a finger presses. A checkbox's target is its label; a
    // link inside a sentence is exempt (WCAG 2.5.8); the keyboard's handle
    // proxies and a formula's scroll box are not pressed.
    const small: string[] = [];
    const targets = document.querySelectorAll<HTMLElement>(
      'button, a[href], input, select, summary, [role="button"]',
    );
    for (const el of targets) {
      if (!shown(el) || el.closest('.handle-layer')) continue;
      if (el.tagName === 'A' && getComputedStyle(el).display === 'inline') continue;
      const target =
        el instanceof HTMLInputElement && ['checkbox', 'radio'].includes(el.type)
          ? (el.closest('label') ?? el)
          : el;
      const box = target.getBoundingClientRect();
      // Out of the page until focused (the skip link).
      if (box.right <= 0) continue;
      if (box.width < 43.5 || box.height < 43.5)
        small.push(
          `${el.tagName.toLowerCase()} “${(target.textContent || el.getAttribute('aria-label') || el.getAttribute('title') || '').trim().slice(0, 30)}” ${Math.round(box.width)}×${Math.round(box.height)}`,
        );
    }
    return {
      overflow: root.scrollWidth - root.clientWidth,
      figure: onFirstScreen(figure),
      next: next ? onFirstScreen(next) : null,
      slider: slider ? onFirstScreen(slider) : null,
      small,
    };
  });
}

for (const phone of PHONES) {
  test.describe(`a phone of ${phone.width}×${phone.height}`, () => {
    test.use({ viewport: phone, hasTouch: true, isMobile: true });
    for (const [slug, queries] of Object.entries(links)) {
      test(`${slug}: every scene fits the screen, keeps its controls by the figure, and has 44 px targets`, async ({
        page,
      }) => {
        test.setTimeout(90_000);
        const faults: string[] = [];
        await page.goto(`./#/${slug}?${queries[0]}`);
        for (const query of queries) {
          await page.evaluate((hash) => (location.hash = hash), `#/${slug}?${query}`);
          await settled(page);
          const seen = await measure(page);
          const where = `${slug}?${query}`;
          if (seen.overflow > 0) faults.push(`${where}: the page is ${seen.overflow} px too wide`);
          if (seen.figure !== true) faults.push(`${where}: the figure is not on the first screen`);
          if (seen.next === false) faults.push(`${where}: Next is below the first screen`);
          if (seen.slider === false) faults.push(`${where}: the slider is below the first screen`);
          for (const target of seen.small) faults.push(`${where}: small target ${target}`);
        }
        expect(faults).toEqual([]);
      });
    }
  });
}
