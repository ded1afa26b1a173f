/**
 * Fitting wide content to a narrow panel: a matrix, a long expansion or a
 * table is shrunk (down to half size, then it scrolls) so it is seen whole in
 * the side panel, and on a projector, where everything is larger, instead of
 * being cut at the panel's edge. Elements are marked when their content
 * changes, and only marked ones are measured: all are read, then all are
 * written, so the browser lays the page out once per pass, not once per
 * element.
 */

/** Smallest size content is shrunk to before it scrolls instead. */
const SMALLEST = 0.5;

/** Marks `el` to be fitted at the next fitToWidth. */
export function markForFit(el: HTMLElement): HTMLElement {
  el.dataset.fit = 'pending';
  return el;
}

/** Shrinks each marked element under `root` that is wider than its box. */
export function fitToWidth(root: ParentNode): void {
  const pending = [...root.querySelectorAll<HTMLElement>('[data-fit="pending"]')];
  if (!pending.length) return;
  const scales = pending.map(() => 1);
  // Start from the natural size (one write pass).
  for (const el of pending) el.style.fontSize = '';
  // Not everything inside scales with the font (borders, a fixed padding), so
  // a second look corrects what the first ratio left over.
  for (let pass = 0; pass < 2; pass++) {
    const sizes = pending.map((el) => [el.clientWidth, el.scrollWidth]);
    let wrote = false;
    pending.forEach((el, i) => {
      const [box, scroll] = sizes[i];
      if (box > 0 && scroll > box + 1 && scales[i] > SMALLEST) {
        scales[i] = Math.max(SMALLEST, scales[i] * (box / scroll) * 0.98);
        el.style.fontSize = `${scales[i].toFixed(3)}em`;
        wrote = true;
      }
      // Not laid out yet (hidden, or not in the page): try again next time.
      if (pass === 0) el.dataset.fit = box > 0 ? 'done' : 'pending';
    });
    if (!wrote) break;
  }
}

/** Marks everything under `root` that was ever fitted (the panel or the type size changed). */
export function refitAll(root: ParentNode): void {
  for (const el of root.querySelectorAll<HTMLElement>('[data-fit]')) el.dataset.fit = 'pending';
}
