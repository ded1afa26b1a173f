/**
 * Fitting wide content to a narrow panel: a matrix, a long expansion or a
 * table is shrunk (down to half size, then it scrolls) so it is seen whole in
 * the side panel, and on a projector, where everything is larger, instead of
 * being cut at the panel's edge. Elements are marked when their content
 * changes, and only marked ones are measured.
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
  for (const el of root.querySelectorAll<HTMLElement>('[data-fit="pending"]')) {
    el.style.fontSize = '';
    const box = el.clientWidth;
    let scale = 1;
    // Not everything inside scales with the font (borders, a fixed padding), so
    // a second look corrects what the first ratio left over.
    for (
      let pass = 0;
      pass < 2 && box > 0 && el.scrollWidth > box + 1 && scale > SMALLEST;
      pass++
    ) {
      scale = Math.max(SMALLEST, scale * (box / el.scrollWidth) * 0.98);
      el.style.fontSize = `${scale.toFixed(3)}em`;
    }
    // Not laid out yet (hidden, or not in the page): try again next time.
    el.dataset.fit = box > 0 ? 'done' : 'pending';
  }
}

/** Marks everything under `root` that was ever fitted (the panel or the type size changed). */
export function refitAll(root: ParentNode): void {
  for (const el of root.querySelectorAll<HTMLElement>('[data-fit]')) el.dataset.fit = 'pending';
}
