import { eachSceneEnd, expect, sceneLinks, test } from './fixtures';

/**
 * A lecturer's laptop, 1366×768 (#19), in every scene of every lesson at its
 * first and last step: the page never scrolls sideways, and no text on it,
 * in the panel or its formulas (subscripts included), is
 * set under 12 px, and no subscript index (P₀) smaller than 12 px text's
 * digits. Read from the page: the root's scroll width and each shown
 * text's computed size. (The figures' own text is held to 12 px by the
 * screen theme's smallest size, as steps.test.ts holds the projector's to 28.)
 */
test.use({ viewport: { width: 1366, height: 768 } });

for (const slug of Object.keys(sceneLinks)) {
  test(`${slug}: at 1366×768 no scene scrolls sideways or sets text under 12 px`, async ({
    page,
  }) => {
    test.setTimeout(90_000);
    const faults = await eachSceneEnd(page, slug, async (where) => {
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
        return {
          overflow: root.scrollWidth - root.clientWidth,
          small: [...small, ...apart],
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
