import type { Page } from '@playwright/test';
import { eachSceneEnd, expect, figureSizes, openHash, sceneLinks, settled, test } from './fixtures';

/**
 * A student on a phone, in every scene of every lesson, at its first and
 * last step: the page is no wider than the screen, nor a table than its box
 * (a linear system excepted); the figure, Next and the slider are on the
 * first screen together; every control is a 44 px target.
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
    // A table no wider than its box: a column scrolled out of sight is lost
    // (hermite's joins ran 384 px in 336, blending's expansions 352). A
    // linear system is the exception: its columns are its unknowns, and it
    // scrolls in its own box.
    const wide: string[] = [];
    for (const table of document.querySelectorAll<HTMLElement>('table')) {
      const name = table.getAttribute('aria-label') ?? '';
      if (!shown(table) || /system/i.test(name)) continue;
      const room = table.parentElement!.clientWidth;
      if (table.scrollWidth > room + 1)
        wide.push(`table “${name}” ${table.scrollWidth} px in ${room}`);
    }
    return {
      overflow: root.scrollWidth - root.clientWidth,
      wide,
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
    for (const slug of Object.keys(sceneLinks)) {
      test(`${slug}: every scene fits the screen, keeps its controls by the figure, and has 44 px targets`, async ({
        page,
      }) => {
        test.setTimeout(90_000);
        const faults = await eachSceneEnd(page, slug, async (where) => {
          const seen = await measure(page);
          const found: string[] = [];
          if (seen.overflow > 0) found.push(`${where}: the page is ${seen.overflow} px too wide`);
          if (seen.figure !== true) found.push(`${where}: the figure is not on the first screen`);
          if (seen.next === false) found.push(`${where}: Next is below the first screen`);
          if (seen.slider === false) found.push(`${where}: the slider is below the first screen`);
          for (const target of seen.small) found.push(`${where}: small target ${target}`);
          for (const table of seen.wide) found.push(`${where}: ${table}`);
          return found;
        });
        expect(faults).toEqual([]);
      });
    }
  });
}

test.describe('a phone of 360×740, step by step', () => {
  test.use({ viewport: PHONES[0], hasTouch: true, isMobile: true });
  for (const slug of Object.keys(sceneLinks)) {
    // On a phone the step's sentence is said whole under the figure, in as
    // many lines as it needs: the figures keep one size through a scene (#19),
    // whatever the step, and Next's "Scene done" after its last step.
    test(`${slug}: each scene's figures keep one size through its steps`, async ({ page }) => {
      test.setTimeout(120_000);
      const faults: string[] = [];
      const scenes = new Map<string, string>();
      for (const query of sceneLinks[slug])
        scenes.set(/(?:^|&)scene=([^&]*)/.exec(query)?.[1] ?? '', query);
      await page.goto(`./#/${slug}?${[...scenes.values()][0]}`);
      for (const [scene, query] of scenes) {
        await openHash(page, `#/${slug}?${query}`);
        await page.keyboard.press('Home');
        await settled(page);
        const status = page.locator('.step-status');
        const count = Number(/Step \d+\/(\d+)/.exec((await status.textContent()) ?? '')?.[1] ?? 0);
        const first = await figureSizes(page);
        const next = page.locator('.steps button', { hasText: /^Next/ });
        for (let k = 1; k <= count + 1; k++) {
          // The lesson's last scene has no "Scene done" after it.
          if (!(await next.isEnabled())) break;
          await next.click();
          await settled(page);
          const sizes = await figureSizes(page);
          const at = k > count ? '“Scene done”' : `step ${k}`;
          if (sizes !== first)
            faults.push(`${scene || 'first scene'}: ${at}: ${sizes}, step 0: ${first}`);
        }
      }
      expect(faults).toEqual([]);
    });
  }
});

test.describe('a student with a phone in hand', () => {
  test.use({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });

  test('past a scene’s last step, Next says “Scene done” before the next scene opens', async ({
    page,
  }) => {
    await page.goto('./#/de-casteljau?scene=cubic&step=5');
    const status = page.locator('.step-status');
    await expect(status).toHaveText(/^Step 5\/5/);
    await page.getByRole('button', { name: 'Next ▶' }).tap();
    await expect(status).toHaveText('Scene done. Next: Quadratic.');
    await page.getByRole('button', { name: 'Next scene ▶' }).tap();
    await expect(status).toHaveText(/^Step 0\/4/);
    await expect(page.locator('[data-scene="quadratic"]')).toHaveAttribute('aria-pressed', 'true');
  });

  test('a scene opened while the step line is off the page still keeps room for its longest step', async ({
    page,
  }) => {
    // A page mounting late on a busy machine: the step line joins the page
    // some frames after the scene opens. The room for the scene's longest step
    // is measured once it is there (measured only on the next frame, the scene
    // kept none, and its figures shrank at its first long step).
    await page.goto('./#/hermite?scene=one&step=0');
    await settled(page);
    const held = await page.evaluate(async () => {
      const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
      const steps = document.querySelector('.steps')!;
      const [parent, next] = [steps.parentNode!, steps.nextSibling];
      steps.remove();
      document.querySelector<HTMLButtonElement>('button[data-scene="long"]')!.click();
      for (let i = 0; i < 6; i++) await frame();
      parent.insertBefore(steps, next);
      for (let i = 0; i < 3; i++) await frame();
      return steps.querySelector<HTMLElement>('.step-status')!.style.minHeight;
    });
    await settled(page);
    expect(held).toMatch(/^\d+px$/);
    // The figures keep that size from step 0 to the scene's longest step.
    const first = await figureSizes(page);
    const next = page.getByRole('button', { name: 'Next ▶' });
    for (let k = 1; k <= 7; k++) {
      await next.tap();
      await settled(page);
      expect(await figureSizes(page), `step ${k}`).toBe(first);
    }
  });

  test('a tapped point offers its Delete button, and the point goes', async ({ page }) => {
    await page.goto('./#/de-casteljau?p=0,0;1,2;3,2;4,0&step=0');
    const proxy = page.locator('[data-handle="p1"]');
    const box = (await proxy.boundingBox())!;
    await page.touchscreen.tap(box.x + box.width / 2, box.y + box.height / 2);
    const remove = page.getByRole('button', { name: 'Delete P1' });
    await expect(remove).toBeVisible();
    const size = (await remove.boundingBox())!;
    expect(size.height).toBeGreaterThanOrEqual(44);
    await remove.tap();
    await expect(page).toHaveURL(/p=0,0;3,2;4,0&/);
  });

  test('the text opens under the figure in one tap, with the figure kept in sight', async ({
    page,
  }) => {
    await page.goto('./#/road');
    await settled(page);
    await page.getByRole('button', { name: 'Text and numbers ▾' }).tap();
    const figure = page.locator('.figure:not([hidden])').first();
    const panel = page.locator('aside.panel');
    await expect
      .poll(async () => {
        const [f, p] = [(await figure.boundingBox())!, (await panel.boundingBox())!];
        // The figure is on screen at the top, the text starts right under it.
        return f.y >= -1 && f.y + f.height <= 844 && Math.abs(p.y - (f.y + f.height)) < 200;
      })
      .toBe(true);
    await page.getByRole('button', { name: 'Figure only ▴' }).tap();
    await expect.poll(() => page.evaluate(() => window.scrollY)).toBe(0);
  });

  test('turning the phone keeps the reading position', async ({ page }) => {
    await page.goto('./#/road');
    await settled(page);
    const heading = page.locator('aside.panel h2:visible').nth(1);
    await heading.evaluate((el) => window.scrollTo(0, el.getBoundingClientRect().top + scrollY));
    // Let the page note what is at the top (it does so once per frame of scrolling).
    await page.evaluate(
      () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))),
    );
    await page.setViewportSize({ width: 844, height: 390 });
    await expect.poll(async () => Math.abs((await heading.boundingBox())!.y)).toBeLessThan(40);
  });

  test('help starts with the finger', async ({ page }) => {
    await page.goto('./#/de-casteljau');
    await page.getByRole('button', { name: '?' }).tap();
    const dialog = page.getByRole('dialog', { name: 'Help' });
    await expect(dialog.locator('h3').first()).toHaveText('With a finger');
    const box = (await dialog.boundingBox())!;
    expect(box.width).toBeLessThanOrEqual(390);
    await expect(page.locator('.panel .note').first()).not.toContainText(
      /double-click|right-click/,
    );
  });
});
