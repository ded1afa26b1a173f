import katex from 'katex';
import 'katex/dist/katex.min.css';
import { canSetRowsApart, markForFit, rowsAreApart } from './fit';
import { freeBox, reshapeBox, sameWidth } from './liveBoxes';
import { sayTex } from './notation';
import { rowsApart } from './rowsApart';
import { typesetSoon } from './typesetBudget';
import { pointerHeld, waitUnseen, watchSeen, whenReleased } from './unseen';
import { setClass, setText } from '../app/dom';

const OPTIONS = {
  throwOnError: false,
  output: 'htmlAndMathml' as const,
  // Only our own number slots (\htmlData) are trusted; no other HTML extension.
  trust: (context: { command: string }) => context.command === '\\htmlData',
  strict: false as const,
};

/**
 * Typesets TeX into `el` with the bundled KaTeX (no CDN), unless `el` already
 * shows exactly this TeX. The TeX is built by the lessons from numbers they
 * computed; KaTeX builds DOM nodes, not markup.
 */
export function renderFormula(el: HTMLElement, tex: string, display = false): void {
  if (el.dataset.tex === tex) return;
  el.dataset.tex = tex;
  typesetSoon(el, () => {
    katex.render(sayTex(asFitted(el, tex, display)), el, { ...OPTIONS, displayMode: display });
    if (display) markForFit(el);
  });
  if (display)
    canSetRowsApart(el, {
      has: () => rowsApart(el.dataset.tex ?? '') !== null,
      set: () => {
        katex.render(sayTex(asFitted(el, el.dataset.tex ?? '', true)), el, {
          ...OPTIONS,
          displayMode: true,
        });
        markForFit(el);
      },
    });
}

/**
 * The TeX a display formula is typeset from: its own, or with its aligned
 * rows apart where the fit found them too wide for its box (see fit.ts).
 */
const asFitted = (el: HTMLElement, tex: string, display: boolean): string =>
  (display && rowsAreApart(el) && rowsApart(tex)) || tex;

/** A new element holding a typeset formula (for formulas that never change). */
export function formula(tex: string, display = false): HTMLElement {
  const el = document.createElement(display ? 'div' : 'span');
  setClass(el, display ? 'formula display' : 'formula');
  renderFormula(el, tex, display);
  return el;
}

/** Marks where a live number goes in a LiveFormula's TeX. */
export const SLOT = '\\val';

/**
 * A live formula's TeX with its numbers filled in: for the MathML's copy of
 * the TeX, and for a step's formula in presenter view.
 */
export const filled = (parts: { shape: string; values: readonly string[] }): string =>
  parts.shape.split(SLOT).reduce((tex, part, i) => tex + (parts.values[i - 1] ?? '') + part);

/**
 * A formula whose shape is typeset once and whose numbers change as text: the
 * TeX has `\val` wherever a number goes, and `set` fills them in. Only a new
 * shape (another number of terms, say) typesets again; a drag that changes
 * the numbers writes a few text nodes.
 */
export class LiveFormula {
  readonly element: HTMLElement;
  /** The shape typeset now, and the one asked for last (they differ while it waits for a frame). */
  private shape: string | null = null;
  private wanted: string | null = null;
  private latest: { shape: string; values: readonly string[] } = { shape: '', values: [] };
  private slots: { html: HTMLElement; mathml: Element | null; text: string; copied: string }[] = [];
  private annotation: Element | null = null;
  /** The shape and numbers written last, whose TeX the MathML's annotation holds. */
  private written: { shape: string; values: readonly string[] } = { shape: '', values: [] };

  constructor(
    private readonly display = false,
    /** Called each time a new shape has been typeset (its size may have changed). */
    private readonly typesetDone?: () => void,
  ) {
    this.element = document.createElement(display ? 'div' : 'span');
    setClass(this.element, display ? 'formula display live' : 'formula live');
    watchSeen(this.element, this);
    if (display)
      canSetRowsApart(this.element, {
        has: () => this.shape !== null && rowsApart(this.shape) !== null,
        set: () => {
          if (this.shape === null) return;
          this.typeset(this.shape);
          this.fill(this.latest);
        },
      });
  }

  /** The shape typeset now (null before the first). */
  get typesetShape(): string | null {
    return this.shape;
  }

  /** The shape and its numbers, as two arguments or as `FormulaParts` (see formulaParts.ts). */
  set(
    shape: string | { shape: string; values: readonly string[] },
    values?: readonly string[],
  ): void {
    const parts = typeof shape === 'string' ? { shape, values: values ?? [] } : shape;
    this.latest = parts;
    if (parts.shape === this.wanted) {
      // Its shape is typeset (or waits to be, with these newest numbers).
      if (parts.shape === this.shape) this.fill(parts);
      return;
    }
    this.wanted = parts.shape;
    typesetSoon(this, () => {
      this.typeset(this.latest.shape);
      this.fill(this.latest);
      this.typesetDone?.();
    });
  }

  /** Writes the numbers that waited for it to come into view (see unseen.ts). */
  catchUp(): void {
    if (this.latest.shape === this.shape) this.fill(this.latest);
  }

  private fill(parts: { shape: string; values: readonly string[] }): void {
    if (waitUnseen(this.element, this)) return;
    let changed = false;
    let reshaped = false;
    parts.values.forEach((value, i) => {
      const slot = this.slots[i];
      if (!slot) return;
      const text = value.replace(/^-/, '−');
      if (text === slot.text) return;
      changed = true;
      // Wider or narrower: its box takes the new size (see liveBoxes.ts), or
      // keeps its width through a drag, and then the formula is as wide as it was.
      if (!sameWidth(text, slot.text) && reshapeBox(slot.html, text)) reshaped = true;
      slot.text = text;
      setText(slot.html, text);
    });
    if (!changed) return;
    this.written = parts;
    // Wider or narrower numbers: a display formula is fitted to the panel again
    // (at the start of the next frame, on a clean layout: one read of its
    // width). The typeset digits are all one width, so 1.25 → 1.37 needs none.
    if (this.display && reshaped) markForFit(this.element);
    // The MathML copy, for assistive tools and copying as TeX, is laid out by
    // Chromium as well: nobody reads it mid-drag (in hermite it was a fifth of
    // the frame, 50.7 → 40.1 ms), so it is written when the pointer is let go.
    if (pointerHeld()) whenReleased(this.writeCopy);
    else this.writeCopy();
  }

  /** The MathML copy: the numbers as shown, and the TeX as typeset with them filled in. */
  private readonly writeCopy = (): void => {
    for (const slot of this.slots) {
      if (slot.copied === slot.text) continue;
      slot.copied = slot.text;
      if (slot.mathml) setText(slot.mathml, slot.text);
    }
    if (this.annotation) setText(this.annotation, sayTex(filled(this.written)));
  };

  private typeset(shape: string): void {
    this.shape = shape;
    let k = 0;
    // Each slot starts as a unique marker, so its MathML twin can be found too.
    const tex = shape.split(SLOT).reduce((acc, part, i) => {
      if (i === 0) return part;
      // \mathord keeps a slot apart from a space or text before it (else KaTeX merges them).
      const slot = `\\htmlData{slot=${k}}{\\mathord{\\text{§${k}§}}}`;
      k++;
      return acc + slot + part;
    });
    katex.render(sayTex(asFitted(this.element, tex, this.display)), this.element, {
      ...OPTIONS,
      displayMode: this.display,
    });
    this.annotation = this.element.querySelector('annotation');
    const mtexts = [...this.element.querySelectorAll('mtext')];
    this.slots = [];
    for (let i = 0; i < k; i++) {
      const marker = `§${i}§`;
      const enclosing = this.element.querySelector(`[data-slot="${i}"]`);
      // The innermost element holding the marker's text: its text is what changes.
      const inner =
        [...(enclosing?.querySelectorAll('*') ?? [])].find(
          (e) => e.childElementCount === 0 && e.textContent === marker,
        ) ?? enclosing;
      const mathml = mtexts.find((m) => m.textContent === marker) ?? null;
      if (!(inner instanceof HTMLElement)) continue;
      freeBox(inner);
      this.slots.push({ html: inner, mathml, text: '', copied: '' });
    }
    if (this.display) markForFit(this.element);
  }
}

/** A number as TeX: fixed digits, no "-0". */
export function texNumber(value: number, digits = 2): string {
  const text = value.toFixed(digits);
  return /^-0\.?0*$/.test(text) ? text.slice(1) : text;
}

/** A point as TeX, `(1.00,\ 2.00)`: each coordinate by texNumber. */
export function texPoint(p: readonly number[], digits = 2): string {
  return `(${p.map((v) => texNumber(v, digits)).join(',\\ ')})`;
}

/** The TeX shape of a point with live coordinates: `(\val,\ \val)`. */
export const slotPoint = (dimension = 2) =>
  `(${Array.from({ length: dimension }, () => SLOT).join(',\\ ')})`;
