/**
 * What the clicker and presenter view promise on every lesson (the
 * teaching-from-the-front issue), as checks the registry-wide specs run on a
 * page they have open anyway: the keyboard walk (keyboard.spec.ts) and the
 * presenter pictures (pictures.spec.ts). Expected behaviour comes from the
 * issue's rules (one step per press, values untouched, ≥ 28 px), read from the
 * link and the DOM, never from the app's own verdicts.
 */
import type { Locator, Page } from '@playwright/test';
import { expect, hashState, settled, snapshot } from './fixtures';

/** The link's fields without the views (a pan is not a step). */
export function fields(page: Page): Record<string, string> {
  return Object.fromEntries(
    Object.entries(hashState(page)).filter(([key]) => !key.startsWith('view.')),
  );
}

/** What changed between two links, as `key: before → after`. */
export function changes(a: Record<string, string>, b: Record<string, string>): string[] {
  const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
  return [...keys].filter((k) => a[k] !== b[k]).map((k) => `${k}: ${a[k]} → ${b[k]}`);
}

/** One clicker press forward: the step field went up by one, or the scene changed (to its step 0). */
function isOneStepForward(before: Record<string, string>, after: Record<string, string>): boolean {
  const changed = changes(before, after);
  if (before.scene !== after.scene) return true;
  if (changed.length !== 1) return false;
  const key = changed[0].split(':')[0];
  return Number(after[key]) === Number(before[key]) + 1;
}

/** The value a control shows, to check a clicker key left it alone. */
async function valueOf(control: Locator, kind: string): Promise<string> {
  // A point: the one that has focus (the list of points may grow with the step).
  if (kind === 'point')
    return control.page().evaluate(() => document.activeElement?.getAttribute('aria-label') ?? '');
  return control.evaluate((el) => {
    if (el instanceof HTMLInputElement)
      return el.type === 'checkbox' || el.type === 'radio' ? String(el.checked) : el.value;
    return el.getAttribute('aria-label') ?? el.textContent ?? '';
  });
}

/** The kinds of control a lesson page has, each the first of its kind that is visible. */
function controls(page: Page): [string, Locator][] {
  const lesson = page.locator('.lesson-page');
  return [
    ['slider', lesson.locator('input[type=range]:visible').first()],
    ['number field', lesson.locator('input[type=number]:visible').first()],
    ['checkbox', lesson.locator('input[type=checkbox]:visible').first()],
    ['radio button', lesson.locator('input[type=radio]:visible').first()],
    ['scene button', lesson.locator('button[data-scene]').first()],
    ['step button', lesson.getByRole('button', { name: 'Next ▶' })],
    ['point', lesson.locator('.handle-proxy').first()],
  ];
}

/**
 * PageDown and PageUp step once whatever has focus (each kind of control the
 * lesson shows, and a point), and leave the control alone; Space on a checkbox
 * ticks it and does not step.
 */
export async function clickerStepsWhateverHasFocus(page: Page, slug: string): Promise<void> {
  // The first scene at its first step: there is always a next step.
  await page.locator('button[data-scene]').first().click();
  await settled(page);
  let tried = 0;
  /** The link's field that holds the step, as the first press shows it. */
  let stepKey: string | null = null;
  for (const [kind, control] of controls(page)) {
    if ((await control.count()) === 0) continue;
    tried++;
    await control.focus();
    const value = await valueOf(control, kind);
    const before = fields(page);
    await page.keyboard.press('PageDown');
    await settled(page);
    const after = fields(page);
    expect(
      isOneStepForward(before, after),
      `${slug}, focus on a ${kind}: one step forward (${changes(before, after).join('; ')})`,
    ).toBe(true);
    // A new scene sets its own values; within a scene nothing else may move.
    if (before.scene === after.scene) {
      stepKey = changes(before, after)[0].split(':')[0];
      expect(await valueOf(control, kind), `${slug}: the ${kind} kept its value`).toBe(value);
    }
    await page.keyboard.press('PageUp');
    await settled(page);
    expect(changes(before, fields(page)), `${slug}, ${kind}: PageUp went back`).toEqual([]);
    expect(await valueOf(control, kind), `${slug}: the ${kind} kept its value`).toBe(value);
  }
  expect(tried).toBeGreaterThanOrEqual(2);

  // A checkbox's own key is Space: it ticks the box and does not step.
  const box = page.locator('.lesson-page input[type=checkbox]:visible').first();
  if ((await box.count()) > 0 && stepKey !== null) {
    await box.focus();
    const checked = await box.isChecked();
    const before = fields(page);
    await page.keyboard.press(' ');
    await settled(page);
    expect(await box.isChecked()).toBe(!checked);
    const after = fields(page);
    // The box's own change only (a lesson may show a new option's whole
    // construction with it), never the clicker's one step and nothing more.
    const changed = changes(before, after);
    expect(changed.length > 0, 'Space ticked the box').toBe(true);
    expect(
      changed.length === 1 && changed[0].startsWith(`${stepKey}:`),
      `Space on a checkbox does not step (${changed.join('; ')})`,
    ).toBe(false);
    expect(after.scene).toBe(before.scene);
  }
}

/**
 * The texts on screen set under `px` CSS pixels, with their sizes: every text
 * node a reader sees (a formula's subscripts included; not KaTeX's MathML
 * copy, nor zero-width struts, nor hidden text), read from its computed size.
 */
export function textsUnder(page: Page, px: number): Promise<string[]> {
  return page.evaluate((px) => {
    const found: string[] = [];
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const el = node.parentElement;
      // Zero-width characters (KaTeX's struts) are not text anyone reads.
      if (!el || !/[^\s\u200b-\u200f\u2060\ufeff]/.test(node.textContent ?? '')) continue;
      if (el.closest('.katex-mathml, .visually-hidden, [hidden], dialog:not([open])')) continue;
      const box = el.getBoundingClientRect();
      if (box.width === 0 || box.height === 0 || el.checkVisibility?.() === false) continue;
      const size = parseFloat(getComputedStyle(el).fontSize);
      if (size < px)
        found.push(`${size.toFixed(1)}px “${(node.textContent ?? '').trim().slice(0, 30)}”`);
    }
    return found;
  }, px);
}

/**
 * The caption's words and glyphs that lie under the lecturer's corner button
 * (☰) in presenter view, read from the laid-out text (KaTeX's MathML copy and
 * zero-width struts left out): the button is drawn over them, so the room
 * cannot read them.
 */
export function captionUnderCorner(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const button = document.querySelector('.controls-toggle')?.getBoundingClientRect();
    const caption = document.querySelector('[data-caption]');
    if (!button || button.width === 0 || !caption) return [];
    const found: string[] = [];
    const walker = document.createTreeWalker(caption, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const el = node.parentElement;
      if (!el || !/[^\s\u200b-\u200f\u2060\ufeff]/.test(node.textContent ?? '')) continue;
      if (el.closest('.katex-mathml')) continue;
      const range = document.createRange();
      range.selectNodeContents(node);
      for (const box of range.getClientRects()) {
        const across = Math.min(box.right, button.right) - Math.max(box.left, button.left);
        const down = Math.min(box.bottom, button.bottom) - Math.max(box.top, button.top);
        if (across > 0.5 && down > 0.5)
          found.push(
            `“${(node.textContent ?? '').trim().slice(0, 30)}” (${across.toFixed(0)} × ${down.toFixed(0)} px)`,
          );
      }
    }
    return found;
  });
}

/**
 * Presenter view at 1920×1080 (already on) is legible from the back row: the
 * caption on screen, no text under 28 px; B blanks the screen and a clicker
 * key brings it back without stepping.
 */
export async function legibleFromTheBackRow(page: Page, slug: string): Promise<void> {
  await expect(page.locator('html')).toHaveClass(/projector/);
  await page.keyboard.press('PageDown');
  await settled(page);
  // The side panel is folded away and the caption is on screen.
  await expect(page.getByRole('complementary', { name: 'Explanation' })).toBeHidden();
  // The lecturer's toolbar, slider and steps are off the room's screen until M.
  const tools = page.getByRole('toolbar', { name: 'Lesson tools' });
  const next = page.getByRole('button', { name: 'Next ▶', includeHidden: true });
  await expect(tools).toBeHidden();
  await expect(next).toBeHidden();
  await page.keyboard.press('m');
  await expect(tools).toBeVisible();
  await expect(next).toBeVisible();
  await page.keyboard.press('m');
  await expect(tools).toBeHidden();
  const caption = page.locator('[data-caption]');
  await expect(caption).toBeInViewport({ ratio: 1 });
  await expect(caption).not.toHaveText('');
  const small = await textsUnder(page, 28);
  expect(small, 'texts under 28 px').toEqual([]);
  await snapshot(page, `presenter-${slug}`);

  // B blanks the screen; a clicker key brings it back without stepping.
  const before = fields(page);
  await page.keyboard.press('b');
  const cover = page.locator('[data-blank]');
  await expect(cover).toBeVisible();
  await expect(cover).toBeInViewport({ ratio: 1 });
  await page.keyboard.press('PageDown');
  await expect(cover).toBeHidden();
  await settled(page);
  expect(changes(before, fields(page))).toEqual([]);
}
