/**
 * Fitting wide content to a narrow panel: a matrix, a long expansion or a
 * table is shrunk (down to half size, never with its type under 12 px, and
 * in presenter view with none of its glyphs, subscripts included, under
 * 28 px) so it is seen whole in the side panel, and on a projector,
 * instead of being cut at the panel's edge. A formula still too wide at its
 * smallest is set on several lines, broken after an = or a + as TeX breaks a
 * formula in running text, at full size or as large as its widest piece
 * allows; a block of aligned rows, which cannot break, has its rows set
 * apart first (rowsApart.ts). Only when neither fits does a projector's formula go under its
 * floor (seen whole, down to 12 px: no one scrolls a projected caption);
 * wider still, it scrolls (chooseFit). (Each marked formula's pieces are read twice, for its
 * width and for its lines: one loop would do.) Elements are marked when their content
 * changes, and only marked ones are measured: all are read, then all are
 * written, so the browser lays the page out once per pass, not once per
 * element.
 */

import { freeAllBoxes } from './liveBoxes';

/** Smallest size content is shrunk to before it scrolls instead. */
const SMALLEST = 0.5;
/**
 * Nor is its type shrunk below this many CSS pixels (a laptop's panel, a
 * phone): it takes lines or scrolls instead. A view may also set a floor for
 * every glyph, a formula's subscripts included, `--fit-floor` (presenter
 * view's is 28 px, the back row's smallest): under it only when lines at it
 * would not fit either (chooseFit).
 */
const SMALLEST_PX = 12;

/** Marks `el` to be fitted at the next fitToWidth. */
export function markForFit(el: HTMLElement): HTMLElement {
  el.dataset.fit = 'pending';
  return el;
}

/**
 * Shrinks each marked element under `root` that is wider than its box, or
 * lets it grow back towards its natural size when it has room: one pass of
 * reads, then one of writes. Content scales with its font size, so its
 * natural width is its width now over the scale it has now.
 */
export function fitToWidth(root: ParentNode): void {
  // Formulas whose rows were set apart in this pass: measured again (one more layout, once per shape).
  let apart = false;
  const pending = [...root.querySelectorAll<HTMLElement>('[data-fit="pending"]')];
  if (!pending.length) return;
  const sizes = pending.map((el) => {
    const pieces = lineWidths(el);
    return {
      box: el.clientWidth,
      scroll: el.scrollWidth,
      // Set on lines, its width as one line is the sum of its pieces.
      width: el.classList.contains(WRAPS) ? pieces.sum : contentWidth(el),
      widest: pieces.widest,
      ...typeSizes(el),
      indent: hangingIndent(el),
    };
  });
  pending.forEach((el, i) => {
    const { box, scroll, width, widest, type, glyph, floor, indent } = sizes[i];
    // Not laid out yet (hidden, or not in the page): try again next time.
    if (box <= 0) return;
    el.dataset.fit = 'done';
    const scale = Number(el.dataset.scale ?? '1');
    const wrapped = el.classList.contains(WRAPS);
    const natural = Math.max(width, scroll > box + 1 && !wrapped ? scroll : 0) / scale;
    // The scale at which text now of `size` would be `px` (never under half size).
    const at = (px: number, size: number) => Math.min(1, Math.max(SMALLEST, px / (size / scale)));
    const least = at(SMALLEST_PX, type);
    const line = (widest + indent) / scale;
    const { scale: fitted, wraps } = chooseFit({
      box,
      natural,
      line: widest > 0 ? line : 0,
      readable: Math.max(least, at(floor, glyph)),
      least,
    });
    if (wraps !== wrapped) el.classList.toggle(WRAPS, wraps);
    // Still too wide: it scrolls, so the keyboard must reach it.
    const scrolls = wraps ? line * fitted > box + 1 : natural * fitted > box + 1;
    // Aligned rows too wide even at 12 px: set apart, each free to take lines (rowsApart.ts).
    const rows = rowsSetter.get(el);
    if (scrolls && rows && !rowsAreApart(el) && rows.has()) {
      el.dataset.rows = 'apart';
      rows.set();
      apart = true;
      return;
    }
    if (scrolls !== el.hasAttribute('tabindex')) {
      if (scrolls) el.setAttribute('tabindex', '0');
      else el.removeAttribute('tabindex');
    }
    if (Math.abs(fitted - scale) < 0.005) return;
    el.dataset.scale = fitted.toFixed(3);
    el.style.fontSize = fitted === 1 ? '' : `${fitted.toFixed(3)}em`;
  });
  if (apart) fitToWidth(root);
}

/**
 * A formula's rows, as the fit sets them (given by the formula, formula.ts):
 * whether it has aligned rows to set apart, and its typesetting again, its
 * rows apart or aligned as `rowsAreApart` says, marked for fitting.
 */
export interface RowsSetter {
  has(): boolean;
  set(): void;
}

const rowsSetter = new WeakMap<HTMLElement, RowsSetter>();

/** Lets the fit set `el`'s aligned rows apart when it is too wide for its box even at 12 px. */
export function canSetRowsApart(el: HTMLElement, rows: RowsSetter): void {
  rowsSetter.set(el, rows);
}

/** Whether `el`'s rows are to be typeset apart (the fit found them too wide aligned). */
export const rowsAreApart = (el: HTMLElement): boolean => el.dataset.rows === 'apart';

/** What fitToWidth measured of one element, in CSS pixels at its natural size, and its floors as scales. */
export interface FitMeasure {
  /** The box's width. */
  box: number;
  /** The content's width on one line. */
  natural: number;
  /** Its widest line when set on lines (widest piece and indent), 0 when it cannot break. */
  line: number;
  /** The scale that sets its smallest text at the view's floor (28 px in presenter view). */
  readable: number;
  /** The scale that sets its smallest text at 12 px: under it, it scrolls. */
  least: number;
}

/**
 * The scale and the lines for a measured element: its natural size when it
 * fits; else shrunk to fit, down to the view's floor; else on lines at the
 * floor or larger; else, rather than scrolled out of sight (a formula that
 * cannot break, on a narrow projector), shrunk under the view's floor or set
 * on lines, whichever is larger, down to 12 px; only then does it scroll.
 */
export function chooseFit(m: FitMeasure): { scale: number; wraps: boolean } {
  const oneLine = m.natural > m.box + 1 ? (m.box / m.natural) * 0.98 : 1;
  const onLines = m.line > 0 ? Math.min(1, (m.box / m.line) * 0.98) : 0;
  // At full size when lines are as good as (a hair's breadth from it).
  const lines = { scale: onLines > 0.995 ? 1 : onLines, wraps: true };
  if (oneLine >= m.readable) return { scale: oneLine, wraps: false };
  if (onLines >= m.readable) return lines;
  if (onLines >= m.least && onLines >= oneLine) return lines;
  return { scale: Math.max(m.least, oneLine), wraps: false };
}

/**
 * The content's own width: a formula's typeset pieces from the first one's
 * left to the last one's right (its line box is as wide as its container, so
 * measuring that would keep a shrunk formula shrunk), or the first child (a table).
 */
export function contentWidth(el: HTMLElement): number {
  const html = el.querySelector('.katex-html');
  if (!html) return el.firstElementChild?.getBoundingClientRect().width ?? 0;
  let left = Infinity;
  let right = -Infinity;
  for (const piece of html.children) {
    const box = piece.getBoundingClientRect();
    if (box.width === 0) continue;
    left = Math.min(left, box.left);
    right = Math.max(right, box.right);
  }
  return right > left ? right - left : 0;
}

/** The class of a formula set on several lines (styles.css lets its pieces wrap). */
const WRAPS = 'wraps';

/**
 * A typeset formula's width as one line (the sum of its unbreakable pieces,
 * the widest of its own lines if it has some), and its widest piece: what is
 * left when it is broken after each = and +. 0 and 0 for a table.
 */
function lineWidths(el: HTMLElement): { sum: number; widest: number } {
  const html = el.querySelector('.katex-html');
  if (!html) return { sum: 0, widest: 0 };
  let sum = 0;
  let line = 0;
  let widest = 0;
  for (const piece of html.children) {
    if (piece.classList.contains('newline')) {
      sum = Math.max(sum, line);
      line = 0;
      continue;
    }
    const width = piece.getBoundingClientRect().width;
    line += width;
    widest = Math.max(widest, width);
  }
  return { sum: Math.max(sum, line), widest };
}

/** How far a wrapped formula's further lines are set in (styles.css: 1.5em of its typeset size). */
function hangingIndent(el: HTMLElement): number {
  const katex = el.querySelector('.katex');
  return katex ? 1.5 * (parseFloat(getComputedStyle(katex).fontSize) || 0) : 0;
}

/**
 * The element's type size, or its table cells' where they are set smaller (a
 * data table is 0.85 of its box's size): what the 12 px floor is for. Its
 * smallest glyphs, a formula's smallest script (a subscript is 0.7 of its
 * formula's size; KaTeX sets every change of size with its class `sizing`),
 * and the view's floor for them, `--fit-floor` (presenter view's 28 px), or
 * none. One read of the element's style for both of its own.
 */
function typeSizes(el: HTMLElement): { type: number; glyph: number; floor: number } {
  const style = getComputedStyle(el);
  let type = parseFloat(style.fontSize) || 16;
  const floor = parseFloat(style.getPropertyValue('--fit-floor')) || 0;
  const cell = el.querySelector('td, th');
  if (cell) type = Math.min(type, parseFloat(getComputedStyle(cell).fontSize) || type);
  // Read only where a view sets a floor for them (the normal view's drag
  // frames, which refit formulas, are spared the reads).
  let glyph = type;
  if (floor > 0)
    for (const script of el.querySelectorAll('.katex-html .sizing'))
      glyph = Math.min(glyph, parseFloat(getComputedStyle(script).fontSize) || glyph);
  return { type, glyph, floor };
}

/** Marks everything under `root` that was ever fitted, and every live number's box (the panel, the fonts or the type size changed). */
export function refitAll(root: ParentNode): void {
  // Its box may now hold its rows aligned: tried again (and set apart again in the same pass if not).
  for (const el of root.querySelectorAll<HTMLElement>('[data-rows="apart"]')) {
    delete el.dataset.rows;
    rowsSetter.get(el)?.set();
  }
  for (const el of root.querySelectorAll<HTMLElement>('[data-fit]')) el.dataset.fit = 'pending';
  freeAllBoxes(root);
}
