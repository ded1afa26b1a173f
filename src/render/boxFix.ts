/**
 * Fixing a box: where an element's text sits, read for many elements at once
 * (one layout), and the styles that hold it at that size as a layout boundary
 * (size and layout containment). A live number's box (liveBoxes.ts) and a
 * table cell's words held through a drag (cellBoxes.ts) are fixed so.
 */

/**
 * The state of a live number's box: `free` (its own size, to be measured),
 * `fixed`, `loose` (left as it is), or `held` (a cell's words, through a drag: holdCells).
 */
export const BOX = 'box';

/** What a fixed box sets; freeing it clears all of them. */
export const FIXED_STYLE = [
  'display',
  'width',
  'height',
  'vertical-align',
  'contain',
  'white-space',
];

/** Where an element's text sits: its lines, its box, its baseline and its type size. */
export interface Measure {
  lines: number;
  box: { width: number; top: number; bottom: number };
  baseline: number;
  font: number;
}

/** Where each element's text sits now, all read at once (one layout). */
export function measure(els: readonly HTMLElement[]): Measure[] {
  if (els.length === 0) return [];
  // A zero-size inline block sits on the number's baseline: where its bottom is says where the baseline is.
  const probes = els.map((el) => {
    const probe = document.createElement('span');
    probe.style.cssText = 'display:inline-block;width:0;height:0';
    el.append(probe);
    return probe;
  });
  const measured = els.map((el, i) => ({
    lines: el.getClientRects().length,
    box: extent(el),
    baseline: probes[i].getBoundingClientRect().bottom,
    font: parseFloat(getComputedStyle(el).fontSize),
  }));
  for (const probe of probes) probe.remove();
  return measured;
}

/**
 * Fixes `el`'s box at the size `m` measured, as `state`; returns its width in
 * ems, or null (and leaves it as it is) when it is not on one line and not held.
 */
export function fix(el: HTMLElement, m: Measure, state: 'fixed' | 'held'): number | null {
  const { lines, box, baseline, font } = m;
  // Words held through a drag may be on two lines: their box is as wide as they are, and they break as before.
  const wraps = state === 'held' && lines > 1;
  if ((lines !== 1 && !wraps) || !(font > 0) || box.width <= 0) return null;
  const em = (px: number) => `${(px / font).toFixed(4)}em`;
  // A hair wider than measured, so rounding never breaks its line.
  const width = Number(((box.width + 0.05) / font).toFixed(4));
  el.style.width = `${width}em`;
  el.style.height = em(box.bottom - box.top);
  // A contained inline block sits on its bottom edge: lower it by the number's depth.
  el.style.verticalAlign = em(baseline - box.bottom);
  if (!wraps) el.style.whiteSpace = 'nowrap';
  el.style.display = 'inline-block';
  el.style.contain = 'size layout style';
  el.dataset[BOX] = state;
  return width;
}

/** The element's box with everything in it (a subscript set lower than its text). */
function extent(el: HTMLElement): { width: number; top: number; bottom: number } {
  const own = el.getBoundingClientRect();
  let [top, bottom] = [own.top, own.bottom];
  for (const child of el.querySelectorAll('*')) {
    const box = child.getBoundingClientRect();
    if (box.height === 0) continue;
    top = Math.min(top, box.top);
    bottom = Math.max(bottom, box.bottom);
  }
  return { width: own.width, top, bottom };
}
