/**
 * A live number's box, fixed at the size its text has: a panel number that a
 * drag changes is then laid out on its own, not with its formula, its table
 * and the page round them. Its box is a layout boundary (size and layout
 * containment at the size it measured), so Chromium lays out and paints only
 * that box again: in quadratic's panel, 17 numbers a frame had the whole
 * document laid out (2.2 ms) and painted (2.5 ms) on every drag frame.
 *
 * A number whose text changes shape (a digit more, a minus sign) frees its
 * box; freed boxes are measured at the start of the next frame, on a clean
 * layout, all at once (one layout, then one pass of writes). While a pointer
 * is held nothing is measured (that lays the page out at the start of a
 * frame): a number that becomes no wider than the text its box was measured
 * at keeps the box (`−0.014` → `0` → `1.02`), and one that grows takes the
 * width its glyphs are estimated to need (`0` → `0.25`) and keeps it till the
 * drag ends; both are measured again once the pointer is let go. Left loose, such a number had the whole
 * document laid out and painted on every drag frame (quadratic's matrices,
 * surface's patch formulas). Sizes are set in ems, so a formula shrunk to fit
 * its panel keeps its numbers' boxes right.
 */

import { BOX, FIXED_STYLE, fix, measure } from './boxFix';
import { pointerHeld, whenReleased } from './unseen';

/**
 * Are two texts of a number set equally wide? They are when they differ only
 * in digits: KaTeX's digits are 0.5em each.
 */
export const sameWidth = (a: string, b: string): boolean =>
  a.length === b.length && a.replace(/\d/g, '0') === b.replace(/\d/g, '0');

/** The text each fixed box was measured at. */
const measuredAt = new WeakMap<HTMLElement, string>();
/** The width in ems each fixed box was measured at. */
const measuredEm = new WeakMap<HTMLElement, number>();
/** Boxes kept through a drag at a size their text no longer has: measured when it is let go. */
const kept = new Set<HTMLElement>();

/** Ems a glyph of a number takes in KaTeX's main font; other glyphs are not estimated. */
const NUMBER_GLYPH_EM: Readonly<Record<string, number>> = {
  '.': 0.278,
  ',': 0.278,
  '−': 0.778,
  '-': 0.778,
  '+': 0.778,
  ' ': 0.25,
};

/** A number's width in ems, or NaN when it holds anything but digits, signs and points. */
function numberWidth(text: string): number {
  let em = 0;
  for (const glyph of text) em += /\d/.test(glyph) ? 0.5 : (NUMBER_GLYPH_EM[glyph] ?? NaN);
  return em;
}

/**
 * Does `text` fit a box measured at `measured`? When it is a number no wider,
 * both in KaTeX's glyphs and in characters (a table's figures are all one
 * width), or differs from it only in digits.
 */
export function fitsBox(text: string, measured: string): boolean {
  if (sameWidth(text, measured)) return true;
  return text.length <= measured.length && numberWidth(text) <= numberWidth(measured);
}

/**
 * `el`'s text is about to become `text`, a different shape: its box is freed
 * to take the new size, unless a pointer is held and the text is a number.
 * Then the box keeps its measured width if the text fits it, or takes the
 * width the text is estimated to need if it grew, and it is measured again on
 * release. Returns whether the box's width may have changed (what holds it
 * is to be fitted again); false when it kept the width it had.
 */
export function reshapeBox(el: HTMLElement, text: string): boolean {
  // A cell's words held through a drag keep their box, whatever they become (holdCells).
  if (el.dataset[BOX] === 'held') return false;
  const measured = measuredAt.get(el);
  if (el.dataset[BOX] === 'fixed' && pointerHeld() && measured !== undefined) {
    const em = measuredEm.get(el);
    const width = em === undefined || fitsBox(text, measured) ? em : grownWidth(em, text, measured);
    if (width !== undefined) {
      // A box only grows through a drag: a number flickering between 0 and
      // −0.014 would resize it, and lay the page out, on every other frame.
      const grew = setWidth(el, Math.max(width, parseFloat(el.style.width) || 0));
      if (kept.size === 0) whenReleased(freeKept);
      kept.add(el);
      return grew;
    }
  }
  kept.delete(el);
  freeBox(el);
  return true;
}

/** Sets a box's width in ems; whether that changed it. */
const setWidth = (el: HTMLElement, em: number): boolean => {
  const width = `${em.toFixed(4)}em`;
  if (el.style.width === width) return false;
  el.style.width = width;
  return true;
};

/**
 * Mid-drag, the width in ems of a box for a number that outgrew the text
 * `measured` its box was `em` wide at (0 → 0.25): that width scaled by the
 * glyphs' widths or by the count of characters, whichever grew more (KaTeX's
 * glyphs, a table's figures), so that the number is never cut; undefined when
 * either text is not a number. Measuring it would lay the page out at the
 * start of a frame; left loose, it would have the page laid out on every frame.
 */
export function grownWidth(em: number, text: string, measured: string): number | undefined {
  const [now, then] = [numberWidth(text), numberWidth(measured)];
  if (!(now > 0) || !(then > 0)) return undefined;
  return em * Math.max(now / then, text.length / measured.length);
}

/** After a drag: the boxes kept at their old size take their text's own size, unless it is the same. */
function freeKept(): void {
  for (const el of kept) {
    const measured = measuredAt.get(el);
    const em = measuredEm.get(el);
    if (!el.isConnected) continue;
    if (measured === undefined || em === undefined || !sameWidth(el.textContent ?? '', measured))
      freeBox(el);
    else setWidth(el, em);
  }
  kept.clear();
}

/** Lets `el` take its text's own size again; it is measured and fixed at the next `fixBoxes`. */
export function freeBox<E extends HTMLElement>(el: E): E {
  if (el.dataset[BOX] === 'free') return el;
  if (el.dataset[BOX] === 'fixed') for (const name of FIXED_STYLE) el.style.removeProperty(name);
  el.dataset[BOX] = 'free';
  return el;
}

/** `el` is left to the page's layout again, with no box of its own. */
export function dropBox(el: HTMLElement): void {
  if (!el.dataset[BOX]) return;
  for (const name of FIXED_STYLE) el.style.removeProperty(name);
  delete el.dataset[BOX];
  kept.delete(el);
  measuredAt.delete(el);
  measuredEm.delete(el);
}

/** Every box under `root` measured again (the fonts or the type size changed). */
export function freeAllBoxes(root: ParentNode): void {
  for (const el of root.querySelectorAll<HTMLElement>(`[data-${BOX}]:not([data-${BOX}="held"])`))
    freeBox(el);
}

/**
 * Fixes the box of every freed number under `root` at the size it has now.
 * A number not laid out (hidden) stays free till it shows; one set on more
 * than one line is left loose: a box of one size would cut it or break it
 * differently.
 */
export function fixBoxes(root: ParentNode): void {
  // Mid-drag, a number that grew stays loose (it may grow again next frame: a
  // matrix entry 0 → 0.002 → 0.0025), measured when let go: measuring mid-drag
  // forced a layout of the page at the start of a frame (a 54 ms frame in the
  // blending monkey test, 44 of it here).
  if (pointerHeld()) return;
  // One not laid out (hidden) stays free, to be measured once it shows.
  const free = [...root.querySelectorAll<HTMLElement>(`[data-${BOX}="free"]`)].filter(
    (el) => el.getClientRects().length > 0,
  );
  const measured = measure(free);
  free.forEach((el, i) => {
    const width = fix(el, measured[i], 'fixed');
    if (width === null) {
      el.dataset[BOX] = 'loose';
      return;
    }
    measuredAt.set(el, el.textContent ?? '');
    measuredEm.set(el, width);
  });
}
