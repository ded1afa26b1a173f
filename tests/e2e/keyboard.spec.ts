/**
 * A keyboard-only walk on every lesson (issue #11, item 7): Tab alone reaches
 * every control and every point the page shows, a point moves by its arrow
 * keys, and the clicker keys step the construction from wherever Tab left the
 * focus. No pointer is used after the page opens. Then, on the same page, the
 * clicker keys with the focus on each kind of control (clicker.ts).
 */
import { clickerStepsWhateverHasFocus } from './clicker';
import { expect, lessonFolders, settled, test, linkState } from './fixtures';

const slugs = lessonFolders();

/** What a focusable element is, for the walk: a radio group counts once (arrows move within it). */
const TARGETS = `button, input, select, textarea, a[href], summary, [tabindex], [role]`;

for (const slug of slugs) {
  test(`${slug}: Tab alone reaches every control and point, a point moves by its keys, and PageDown/PageUp step once whatever has focus`, async ({
    page,
  }) => {
    await page.goto(`./#/${slug}`);
    await settled(page);
    // Every control the page shows now, marked with the name the walk knows it by.
    const wanted = await page.evaluate((selector) => {
      const names = new Set<string>();
      let n = 0;
      for (const el of document.querySelectorAll<HTMLElement>(selector)) {
        // A native control counts whatever its tabindex (taken out of the
        // order, it is a defect to find); anything else counts when it is in
        // the order, or plays a control's role.
        const native = el.matches('button, input, select, textarea, a[href], summary');
        const role = /^(button|slider|checkbox|radio|link|tab|spinbutton)$/.test(
          el.getAttribute('role') ?? '',
        );
        if (!native && !role && el.tabIndex < 0) continue;
        if (el.matches(':disabled') || el.closest('[inert], [hidden]')) continue;
        if (!el.checkVisibility({ visibilityProperty: true })) continue;
        const box = el.getBoundingClientRect();
        if (box.width === 0 || box.height === 0) continue;
        const radio = el instanceof HTMLInputElement && el.type === 'radio' && el.name;
        const name = radio
          ? `radio group ${el.name}`
          : `#${n++} ${el.tagName.toLowerCase()} “${(el.getAttribute('aria-label') ?? el.textContent ?? '').trim().slice(0, 40)}”`;
        el.dataset.walk = name;
        names.add(name);
      }
      return [...names];
    }, TARGETS);
    expect(wanted.length, `${slug}: controls to reach`).toBeGreaterThan(5);
    expect(
      wanted.some((name) => name.includes('P')),
      `${slug}: a point among them`,
    ).toBe(true);

    const reached = new Set<string>();
    await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
    const before = await linkState(page);
    for (let press = 0; press < wanted.length * 2 + 20 && reached.size < wanted.length; press++) {
      await page.keyboard.press('Tab');
      const name = await page.evaluate(
        () => (document.activeElement as HTMLElement | null)?.dataset.walk ?? null,
      );
      if (name) reached.add(name);
    }
    expect(
      wanted.filter((name) => !reached.has(name)),
      `${slug}: controls Tab never reached`,
    ).toEqual([]);
    // Walking changes nothing.
    await settled(page);
    expect(await linkState(page)).toEqual(before);

    // A point, reached by Tab, moves by its arrow keys (its label says where it is).
    const point = page.locator('.handle-proxy').first();
    for (let press = 0; press < wanted.length * 2 + 20; press++) {
      if (await point.evaluate((el) => el === document.activeElement)) break;
      await page.keyboard.press('Tab');
    }
    await expect(point).toBeFocused();
    const label = await point.getAttribute('aria-label');
    await page.keyboard.press('ArrowRight');
    await settled(page);
    expect(await point.getAttribute('aria-label'), `${slug}: the point moved`).not.toBe(label);
    expect(await linkState(page), `${slug}: the move is in the link`).not.toEqual(before);
    await page.keyboard.press('Control+z');
    await settled(page);
    expect(await linkState(page), `${slug}: undo takes the move back`).toEqual(before);

    // The clicker steps from here (focus still on the point), and back.
    await page.keyboard.press('End');
    await settled(page);
    const last = await linkState(page);
    await page.keyboard.press('Home');
    await settled(page);
    const first = await linkState(page);
    expect(first, `${slug}: Home and End are different steps`).not.toEqual(last);
    await page.keyboard.press('PageDown');
    await settled(page);
    expect(await linkState(page), `${slug}: PageDown took a step`).not.toEqual(first);
    await page.keyboard.press('PageUp');
    await settled(page);
    expect(await linkState(page), `${slug}: PageUp took it back`).toEqual(first);

    // With the focus on each kind of control: one step, the control untouched.
    await clickerStepsWhateverHasFocus(page, slug);
  });
}
