/**
 * A tiny element builder: text always goes in as text nodes, never as markup,
 * so nothing from a URL can become HTML.
 */
import { subscriptNames } from '../kit/subscripts';
import { freeBox, reshapeBox, sameWidth } from '../render/liveBoxes';
import { minusSigns } from '../render/notation';
import { shownAttribute, shownText } from './notationDom';

export type Child = Node | string | number | null | undefined | false;
type Attrs = Record<string, string | number | boolean | null | undefined | EventListener>;

export function h<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  attrs: Attrs = {},
  ...children: (Child | readonly Child[])[]
): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  for (const [name, value] of Object.entries(attrs)) {
    if (value === null || value === undefined || value === false) continue;
    if (name.startsWith('on') && typeof value === 'function') {
      el.addEventListener(name.slice(2).toLowerCase(), value);
    } else if (value === true) {
      el.setAttribute(name, '');
    } else {
      el.setAttribute(name, String(value));
    }
  }
  append(el, children);
  return el;
}

/**
 * Elements of running prose, and a table's cells: a paragraph, an item, a
 * heading, a cell. Their text names points as the figures label them, P₀ … Pₘ
 * and Nᵢ,₂, whatever the lesson wrote (P0 … Pm, N(i,2)): a table's "P0" beside
 * the figure's P₀ read as another name. Buttons and accessible names keep the
 * plain names a screen reader spells out.
 */
const PROSE = new Set(['P', 'LI', 'H2', 'H3', 'H4', 'SUMMARY', 'FIGCAPTION', 'TD', 'TH']);

export function append(parent: Node, children: (Child | readonly Child[])[]): void {
  for (const child of children.flat()) {
    if (child === null || child === undefined || child === false) continue;
    if (typeof child === 'object') {
      parent.appendChild(child);
      continue;
    }
    const text = asShown(parent, String(child));
    const runs = parent.nodeName === 'LABEL' ? LABEL_INDEX_RUN : INDEX_RUN;
    if (indexable(parent) && runs.test(text)) {
      // One box for the words and their indices: in a row of boxes (a radio's
      // label, a toolbar) each run of text and each index would be a box of
      // its own, "D" on one line and "ₖ" a gap away on another.
      const words = document.createElement('span');
      words.append(...indexedRuns(text, runs));
      parent.appendChild(words);
    } else parent.appendChild(document.createTextNode(text));
  }
}

/**
 * The text as `element` shows it: a negative number with a minus sign (not in
 * code or what the reader types), point names with subscripts in prose.
 */
function asShown(element: Node, text: string): string {
  const shown = text.includes('-') && !asWritten(element) ? minusSigns(text) : text;
  return PROSE.has(element.nodeName) ? subscriptNames(shown) : shown;
}

/**
 * Code (the notes' pseudocode), what the reader types, and a typeset
 * formula (its TeX copy is TeX; its numbers are set by render/formula) keep
 * their text as written.
 */
function asWritten(node: Node): boolean {
  const element = node instanceof Element ? node : node.parentElement;
  return element?.closest('pre, code, .code, textarea, .katex, annotation') != null;
}

/** Unicode subscript runs: ₀–₉ and the letters and signs `subscriptNames` writes. */
const SUBSCRIPT_RUN = /^[₀-₉ᵢⱼₖₘₙₚᵣ₊₋]+$/;

/**
 * An index as `indexedRuns` splits it out: a run of Unicode subscripts, or the
 * capital N of the last point or gradient, P_N, P_{N−1}, D_N, which Unicode has
 * no subscript for (the lesson writes PN, PN−1).
 */
const INDEX_RUN = /([₀-₉ᵢⱼₖₘₙₚᵣ₊₋]+|(?<=(?<![A-Za-z])[PD])N(?:−1)?(?![\p{L}\d(]))/u;

/**
 * In a control's label, also a point's index as the lesson wrote it, P0, P2,1,
 * Pn, Di: it is set as a subscript, its text unchanged, so the control's
 * accessible name ("Hermite H0…H3") stays what scripts and screen readers know.
 */
const LABEL_INDEX_RUN =
  /([₀-₉ᵢⱼₖₘₙₚᵣ₊₋]+|(?<=(?<![A-Za-z])[PD])N(?:−1)?(?![\p{L}\d(])|(?<=(?<![A-Za-z])[PDBQLH])(?:\d+(?:,\d+)?|[ijkmn])(?![\p{L}\d(.]))/u;

/** Elements whose text may hold spans (not an option's, a text area's or an SVG text's). */
const indexable = (node: Node): node is HTMLElement =>
  node instanceof HTMLElement && !['OPTION', 'TEXTAREA', 'TITLE'].includes(node.nodeName);

/**
 * `text` as nodes, each run of subscripts in a span of class "index", which
 * the style sheet sets larger: a font's subscript glyphs are half its size, too
 * small to tell P₁,₀ from P₁,₁ at the back of the room or in a laptop's panel.
 * The nodes' text reads as `text`.
 */
function indexedRuns(text: string, runs = INDEX_RUN): (Node | string)[] {
  return text
    .split(runs)
    .map((run, i) => {
      if (i % 2 === 0) return run;
      const index = document.createElement('span');
      // A letter is set smaller and lowered, as a subscript glyph is drawn.
      index.className = SUBSCRIPT_RUN.test(run) ? 'index' : 'index-letter';
      index.textContent = run;
      return index;
    })
    .filter((run) => run !== '');
}

/** Replaces all children of `el`. */
export function setChildren(el: Element, ...children: (Child | readonly Child[])[]): void {
  el.replaceChildren();
  append(el, children);
}

/** Formats a number for display: fixed decimals, no "-0". */
export function fmt(value: number, digits = 2): string {
  const text = value.toFixed(digits);
  return /^-0\.?0*$/.test(text) ? text.slice(1) : text;
}

export function fmtPoint(p: readonly number[], digits = 2): string {
  return `(${p.map((v) => fmt(v, digits)).join(', ')})`;
}

/**
 * A data table as the panels use it: named for screen readers, one row of
 * column headings, and the body the panel fills in.
 */
export function dataTable(
  label: string,
  columns: readonly (string | Node)[],
  body: HTMLTableSectionElement,
  extraClass = '',
): HTMLTableElement {
  return h(
    'table',
    { class: `data-table${extraClass ? ` ${extraClass}` : ''}`, 'aria-label': label },
    h('thead', {}, h('tr', {}, ...columns.map((c) => h('th', { scope: 'col' }, c)))),
    body,
  );
}

/** Sets an element's text only when it changes (a panel updated every frame writes little). */
export function setText(element: Node, text: string): void {
  if (indexable(element)) return setIndexedText(element, asShown(element, text));
  if (element.nodeName !== 'TEXTAREA') text = asShown(element, text);
  const now = element.textContent;
  if (now !== text && now !== shownText(element, text)) element.textContent = text;
}

/**
 * Sets `text` with its Unicode subscript indices (P₀, D₁₂) in spans of their
 * own (`indexedRuns`), only when it changed.
 */
export function setIndexedText(element: HTMLElement, text: string): void {
  if (text.includes('-') && !asWritten(element)) text = minusSigns(text);
  const now = element.textContent;
  if (now === text || now === shownText(element, text)) return;
  if (element.dataset.live !== undefined) return setLiveNumbers(element, text);
  // A live value in a box of its own (render/liveBoxes.ts): a new shape may need a new box.
  if (element.dataset.box && !sameWidth(text, now)) reshapeBox(element, text);
  const only = element.firstChild;
  if (INDEX_RUN.test(text)) element.replaceChildren(...indexedRuns(text));
  // A live cell or value written every frame: its one text node takes the new
  // words, rather than being replaced by a new one.
  else if (only instanceof Text && only === element.lastChild) only.data = text;
  else element.textContent = text;
}

/** Shows or hides an element only when that changes. */
export function setHidden(element: HTMLElement, hidden: boolean): void {
  if (element.hidden !== hidden) element.hidden = hidden;
}

/** Enables or disables a control only when that changes. */
export function setDisabled(
  element: HTMLButtonElement | HTMLInputElement | HTMLSelectElement,
  disabled: boolean,
): void {
  if (element.disabled !== disabled) element.disabled = disabled;
}

/** Sets an element's classes (the whole `class` attribute) only when they change. */
export function setClass(element: Element, className: string): void {
  if (element.className !== className) element.className = className;
}

/**
 * Sets an attribute only when its value changes: an attribute set to its own
 * value is still a change to the page (style is checked again, an aria-live
 * region may speak again), and a panel is updated on every frame of a drag.
 */
export function setAttr(element: Element, name: string, value: string): void {
  const now = element.getAttribute(name);
  if (now !== value && now !== shownAttribute(element, name, value))
    element.setAttribute(name, value);
}

/**
 * A number in running text: not part of a name (the 0 of P0, of x₀), with its
 * sign and its decimals.
 */
const LIVE_NUMBER = /((?<![\p{L}\p{N}.,′₀-₉])[−+-]?\d+(?:[.,]\d+)*)/u;

/** The words of a live text (its numbers left out), and the boxes its numbers are in. */
const liveParts = new WeakMap<HTMLElement, { words: string; numbers: HTMLElement[] }>();

/**
 * Marks `element` as live text: `setText` then puts each number of it in a
 * box of its own (render/liveBoxes.ts) and leaves the words as they are, so a
 * drag that changes the numbers of a heading or a sentence lays out the
 * numbers' boxes, not the page round them, and the words can still wrap. Not
 * for text that names something from its content (a button, a table cell): a
 * box reads with a space either side of it; a heading is named by `text`.
 */
export function liveText<E extends HTMLElement>(element: E): E {
  element.dataset.live = '';
  return element;
}

/** A live text's words (one more than its numbers: the text before, between and after them) and numbers. */
export function splitNumbers(text: string): { words: string[]; numbers: string[] } {
  const parts = text.split(LIVE_NUMBER);
  return {
    words: parts.filter((_, i) => i % 2 === 0),
    numbers: parts.filter((_, i) => i % 2 === 1),
  };
}

/** `text` into a live element: only its numbers, while its words stay the same. */
function setLiveNumbers(element: HTMLElement, text: string): void {
  const { words, numbers } = splitNumbers(text);
  const key = words.join('\u0000');
  // A box inside words is read with a space either side ("(N = 2 )"): a heading is named by its text.
  if (/^H[1-6]$/.test(element.nodeName)) setAttr(element, 'aria-label', text);
  const shown = liveParts.get(element);
  if (shown && shown.words === key) {
    numbers.forEach((number, i) => setIndexedText(shown.numbers[i], number));
    return;
  }
  const boxes = numbers.map((number) => freeBox(h('span', {}, number)));
  element.replaceChildren(
    ...words.flatMap((word, i) => [...indexedRuns(word), ...(i < boxes.length ? [boxes[i]] : [])]),
  );
  liveParts.set(element, { words: key, numbers: boxes });
}
