import type { LabelBox } from '../../src/render/labels';
import { eachSceneEnd, eachStep, expect, sceneLinks, test } from './fixtures';

/**
 * A lecturer's laptop, 1366×768 (#19), at every step of every scene of every
 * lesson, as a clicker walks them (a middle step's formula was cut): the page never scrolls sideways, nor does its panel,
 * a table or a formula in its box (aligned rows too wide even at 12 px are
 * set apart to take lines, render/rowsApart.ts), a slider or a number field is wide enough to use, a
 * text field shows all of its value, and no text on it in the panel is
 * set under 12 px, and no subscript index (P₀) smaller than 12 px text's
 * digits. (A typeset formula's glyphs are not read: KaTeX marks them
 * aria-hidden, as this check skips assistive copies. A panel formula's
 * subscripts are 11.0 px at full size, 0.7 of its 15.75 px; the fit keeps
 * its type at 12 px or more.) Read from the page: the root's scroll width and each shown
 * text's computed size. (The figures' own text is held to 12 px by the
 * screen theme's smallest size, as steps.test.ts holds the projector's to 28.)
 */
test.use({ viewport: { width: 1366, height: 768 } });

for (const slug of Object.keys(sceneLinks)) {
  test(`${slug}: at 1366×768 no scene scrolls sideways or sets text under 12 px`, async ({
    page,
  }) => {
    test.setTimeout(180_000);
    const faults = await eachStep(page, slug, async (where) => {
      const seen = await page.evaluate(() => {
        const root = document.documentElement;
        const small = new Set<string>();
        const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
        for (let node = walker.nextNode(); node; node = walker.nextNode()) {
          const text = node.textContent?.trim();
          const el = node.parentElement;
          if (!text || !el || !el.checkVisibility({ visibilityProperty: true })) continue;
          // Assistive copies (KaTeX's MathML, visually hidden names) are not seen.
          if (el.closest('.katex-mathml, .visually-hidden, [aria-hidden="true"]')) continue;
          const size = parseFloat(getComputedStyle(el).fontSize);
          if (size < 11.95) small.add(`${size.toFixed(1)}px “${text.slice(0, 20)}”`);
          // A Unicode subscript (P₀, Nᵢ,₂) is drawn at 0.43 of its font's size,
          // a digit at 0.76: it is as legible as 12 px text from 21.2 px up.
          if (/[₀-₉ᵢⱼₖₘₙₚᵣ₊₋]/.test(text) && size * 0.43 < 12 * 0.76 - 0.05)
            small.add(`subscript at ${size.toFixed(1)}px “${text.slice(0, 20)}”`);
        }
        // An index stands against the letter it belongs to, on its line: "Dₖ",
        // not "D" with "ₖ" a gap away on a line of its own (a label laid out
        // as a row of boxes made each run of text and each index a box).
        const apart = new Set<string>();
        for (const index of document.querySelectorAll<HTMLElement>('.index, .index-letter')) {
          const before = index.previousSibling;
          if (!before || !index.checkVisibility({ visibilityProperty: true })) continue;
          if (index.closest('.katex-mathml, .visually-hidden, [aria-hidden="true"]')) continue;
          // Past the "…" of a box cut to its lines (the step's short copy under
          // the figure, whose whole sentence the panel holds): not drawn.
          const box = index.parentElement!;
          const clamped = getComputedStyle(box).webkitLineClamp !== 'none';
          if (clamped && box.scrollHeight > box.clientHeight + 1) {
            const { bottom, right } = box.getBoundingClientRect();
            const own = index.getBoundingClientRect();
            const lineHeight = parseFloat(getComputedStyle(box).lineHeight) || 0;
            // On the last line shown, at or past its end; or on a line not shown.
            if (
              own.top >= bottom - 1 ||
              (own.bottom > bottom - lineHeight && own.right > right - 2 * lineHeight)
            )
              continue;
          }
          const range = document.createRange();
          range.selectNodeContents(before);
          const lines = range.getClientRects();
          const letter = lines[lines.length - 1];
          const own = index.getClientRects()[0];
          if (!letter || !own || own.left < letter.right - 1) continue;
          const middle = (own.top + own.bottom) / 2;
          const onLine = middle >= letter.top - 4 && middle <= letter.bottom + 4;
          if (own.left - letter.right > 2 || !onLine)
            apart.add(
              `“${(before.textContent ?? '').slice(-12)}” and its index “${index.textContent}” apart`,
            );
        }
        // The side panel does not scroll sideways either (a wide table in it did).
        const wide: string[] = [];
        const panel = document.querySelector<HTMLElement>('aside.panel');
        if (panel && panel.scrollWidth > panel.clientWidth + 1)
          wide.push(`the panel is ${panel.scrollWidth - panel.clientWidth} px too wide`);
        // A table as wide as its panel: a column scrolled out of sight in
        // its box is as lost as one off the page.
        for (const table of document.querySelectorAll<HTMLElement>('table')) {
          if (!table.checkVisibility({ visibilityProperty: true })) continue;
          const room = table.parentElement!.clientWidth;
          if (table.scrollWidth > room + 1)
            wide.push(
              `table “${table.getAttribute('aria-label')}” ${table.scrollWidth} px in ${room}`,
            );
        }
        // A formula seen whole: one too wide even at 12 px takes lines (an
        // expansion of ten terms ran 638 px in a 404 px box, scrolled in it).
        for (const box of document.querySelectorAll<HTMLElement>('[data-fit]')) {
          if (!box.checkVisibility({ visibilityProperty: true }) || !box.querySelector('.katex'))
            continue;
          if (box.scrollWidth > box.clientWidth + 1)
            wide.push(
              `formula “${(box.dataset.tex ?? box.textContent ?? '').slice(0, 30)}” ${box.scrollWidth} px in ${box.clientWidth}`,
            );
        }
        // A slider or a number field too narrow to drag or to read its value.
        for (const input of document.querySelectorAll<HTMLInputElement>(
          'input[type="range"], input[type="number"]',
        )) {
          const width = input.getBoundingClientRect().width;
          if (input.checkVisibility({ visibilityProperty: true }) && width < 40)
            wide.push(`“${input.getAttribute('aria-label')}” only ${width.toFixed(0)} px wide`);
        }
        // A field shows the whole of the value it holds (the surface's net
        // cells cut "2.2, 0.9, -0.4" short).
        for (const input of document.querySelectorAll<HTMLInputElement>('input[type="text"]')) {
          if (
            input.checkVisibility({ visibilityProperty: true }) &&
            input.scrollWidth > input.clientWidth + 1
          )
            wide.push(`“${input.getAttribute('aria-label')}” cuts “${input.value}” short`);
        }
        return {
          overflow: root.scrollWidth - root.clientWidth,
          small: [...small, ...apart, ...wide],
        };
      });
      return [
        ...(seen.overflow > 0 ? [`${where}: the page is ${seen.overflow} px too wide`] : []),
        ...seen.small.map((s) => `${where}: ${s}`),
      ];
    });
    expect(faults).toEqual([]);
  });
}

/**
 * Presenter view from the same laptop: a figure's key (its legend box) never
 * hides a point the lecturer drags. Read from the page: the key's box as the
 * figure last placed it, and each handle's keyboard stand-in where the
 * handle is on screen. (b-splines' two meanings of knots hid P₂ here, though
 * the headless model of this size did not.)
 */
for (const slug of Object.keys(sceneLinks)) {
  test(`${slug}: presenter view at 1366×768, no key hides a handle`, async ({ page }) => {
    test.setTimeout(90_000);
    await page.goto(`./#/${slug}`);
    await page.keyboard.press('p');
    await expect(page.locator('html.projector')).toHaveCount(1);
    const faults = await eachSceneEnd(page, slug, (where) =>
      page.evaluate((where) => {
        type Placed = { figure: string; labels: LabelBox[] };
        const lab = (window as unknown as { splineLab: { labels(): Placed[] } }).splineLab;
        const found: string[] = [];
        for (const { figure, labels } of lab.labels()) {
          const host = document.querySelector<HTMLElement>(`.figure[data-figure="${figure}"]`);
          const canvas = host?.querySelector('canvas');
          if (!host || !canvas || !canvas.checkVisibility()) continue;
          const origin = canvas.getBoundingClientRect();
          for (const key of labels.filter((l) => l.boxed && l.text === 'legend'))
            for (const proxy of host.querySelectorAll<HTMLElement>('.handle-proxy')) {
              const box = proxy.getBoundingClientRect();
              if (box.width === 0) continue;
              const [x, y] = [
                box.left + box.width / 2 - origin.left,
                box.top + box.height / 2 - origin.top,
              ];
              // A handle is hidden when the key's box comes within its radius of its centre.
              const dx = Math.max(key.x - x, 0, x - key.x - key.width);
              const dy = Math.max(key.y - y, 0, y - key.y - key.height);
              if (Math.hypot(dx, dy) < box.width / 2)
                found.push(`${where}: ${figure}'s key hides ${proxy.getAttribute('aria-label')}`);
            }
        }
        return found;
      }, where),
    );
    expect(faults).toEqual([]);
  });
}
