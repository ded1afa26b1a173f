/**
 * The caption of presenter view: the scene and step, the step's sentence and
 * its formula, over the figures; held at the height of the scene's tallest
 * step so the figure keeps one size as the clicker steps (#19).
 */
import katex from 'katex';
import { markForFit, fitToWidth, contentWidth, refitAll } from '../render/fit';
import { LiveFormula, filled } from '../render/formula';
import { typesetSoon } from '../render/typesetBudget';
import { sayTex } from '../render/notation';
import { type FormulaParts, slotNumbers } from '../render/formulaParts';
import { h, setHidden, setIndexedText, setText } from './dom';

/**
 * The most of the screen's height a caption reserves for its scene: with the
 * figure at three quarters of a 1920 × 1080 screen or more (#19), the rest is
 * the caption's.
 */
const CAPTION_SHARE = 0.24;
/** Pixels a reservation keeps above its tallest measured step. */
const HEADROOM = 10;

export class CaptionBox {
  /** The caption's element: the scene, the step in words, its formula. */
  readonly element: HTMLElement;
  private readonly sceneText: HTMLElement;
  private readonly stepText: HTMLElement;
  private readonly formulaBox: HTMLElement;
  /** A hidden copy of the caption, where each step of a scene is measured (see reserveFor). */
  // Its own class names (the caption's are the tests' and tools' handle on the
  // caption), styled as the caption's in styles.css.
  private readonly twin = h(
    'div',
    { class: 'caption-twin', 'aria-hidden': 'true' },
    h(
      'p',
      { class: 'caption-text' },
      h('span', { class: 'twin-scene' }),
      h('span', { class: 'twin-step' }),
    ),
    h('div', { class: 'twin-formula' }, h('div', {})),
  );
  private reservedFor = '';
  /** The words and formula shape the caption was last arranged for. */
  private arrangedFor = '';
  private reserved = 0;
  private readonly measureJobs: object[] = [];
  /** The step's formula: its shape typeset once, its numbers written as text during a drag. */
  private readonly formula = new LiveFormula(true, () => this.arrange());

  constructor() {
    this.sceneText = h('span', { class: 'caption-scene' });
    this.stepText = h('span', { class: 'caption-step' });
    this.formulaBox = h('div', { class: 'caption-formula' }, this.formula.element);
    this.element = h(
      'div',
      { class: 'caption', 'data-caption': '' },
      h('p', { class: 'caption-text' }, this.sceneText, this.stepText),
      this.formulaBox,
    );
  }

  /** The caption is a question to the room (styled apart, so the room sees it is one). */
  asking(on: boolean): void {
    this.element.classList.toggle('asking', on);
  }

  /**
   * Holds the caption at the height of the tallest of a scene's steps, so the
   * figure under it keeps one size through the scene (#19). Each step's words
   * and formula are set in a hidden twin of the caption and measured, one per
   * typeset slot (a formula can take a frame's budget on its own); `key` says
   * which scene and screen the reservation is for, and `stepAt(k)` gives step
   * k's caption when its turn comes.
   */
  reserveFor(
    key: string,
    count: number,
    stepAt: (k: number) => { scene: string; step: string; formula: string | FormulaParts | null },
  ): void {
    if (key === this.reservedFor) return;
    this.reservedFor = key;
    this.reserved = 0;
    this.element.style.minHeight = '';
    for (let k = 0; k <= count; k++) {
      const owner = (this.measureJobs[k] ??= {});
      typesetSoon(owner, () => {
        if (this.reservedFor !== key) return;
        // No more than a quarter of the screen less the figure's due: a taller
        // step's formula takes its own room on that step alone.
        const cap = window.innerHeight * CAPTION_SHARE;
        // A few pixels to spare: the live caption's numbers are set as text, and
        // its lines can come out a hair taller than the twin's.
        const height = Math.min(cap, this.measureCaption(stepAt(k)) + HEADROOM);
        if (height > this.reserved) {
          this.reserved = height;
          this.element.style.minHeight = `${Math.ceil(height)}px`;
        }
      });
    }
  }

  /** The height of a caption with these words and formula, at the caption's width. */
  private measureCaption(step: {
    scene: string;
    step: string;
    formula: string | FormulaParts | null;
  }): number {
    const twin = this.twin;
    this.element.after(twin);
    twin.style.width = `${this.element.getBoundingClientRect().width}px`;
    const [scene, words] = twin.querySelectorAll('span');
    setText(scene, step.scene);
    setIndexedText(words, step.step);
    const box = twin.querySelector<HTMLElement>('.twin-formula')!;
    const math = box.firstElementChild as HTMLElement;
    setHidden(box, !step.formula);
    if (step.formula) {
      const tex = typeof step.formula === 'string' ? step.formula : filled(step.formula);
      katex.render(sayTex(tex), math, { throwOnError: false, displayMode: true, strict: false });
    }
    arrange(twin, box, math);
    const height = twin.getBoundingClientRect().height;
    // Out of the page between measurements: no stale copy of a step's words
    // for a reader, a search or a test to find beside the caption.
    twin.remove();
    return height;
  }

  /**
   * The caption of the current step. Its formula is typeset again only when
   * its shape changes: a drag that changes its numbers rewrites their text.
   */
  set(scene: string, step: string, formula: string | FormulaParts | null): void {
    const words = `${scene}\n${step}`;
    setText(this.sceneText, scene);
    setIndexedText(this.stepText, step);
    const parts = formula && (typeof formula === 'string' ? slotNumbers(formula) : formula);
    if (parts) this.formula.set(parts);
    setHidden(this.formulaBox, !parts);
    // Arranged again when the words or the formula's shape change, once the
    // formula is typeset; not as a drag changes its numbers.
    const shape = `${words}\n${parts ? parts.shape : ''}`;
    if (shape !== this.arrangedFor) {
      this.arrangedFor = shape;
      // A new shape is arranged when it is typeset (the formula calls back).
      if (!parts || this.formula.typesetShape === parts.shape) this.arrange();
    }
  }

  private arrange(): void {
    arrange(this.element, this.formulaBox, this.formula.element);
  }

  /**
   * Fitted and arranged again (the formula's fonts arrived: its widths, and
   * the column a formula beside the words was given, were measured before them).
   */
  refit(): void {
    refitAll(this.element);
    this.arrange();
  }

  destroy(): void {
    this.twin.remove();
  }
}

/**
 * Sets a caption's formula beside its words, rather than under them, when it
 * is tall (more than two and a half lines of words: a matrix, a column of
 * equations), narrow enough to leave the words two fifths of the width, and
 * the caption is lower so: the figure then keeps its room (#19). The formula
 * keeps its size; the words wrap in the width it leaves them. (A rule on the
 * formula's own height, not the caption's against its reserve, so that the
 * caption and its measuring twin, whose formulas can differ by a pixel or two,
 * choose alike.)
 */
function arrange(caption: HTMLElement, formulaBox: HTMLElement, formula: HTMLElement): void {
  caption.classList.remove('beside');
  formulaBox.style.minWidth = '';
  // Fitted under the words, at the caption's whole width: at its own size,
  // not at what a narrower column before it (a formula beside the words, a
  // wide formula before it) left it shrunk to.
  if (!formulaBox.hidden) {
    markForFit(formula);
    fitToWidth(caption);
  }
  if (formulaBox.hidden || !caption.getClientRects().length) return;
  const words = caption.querySelector<HTMLElement>('.caption-text')!;
  const line = parseFloat(getComputedStyle(words).lineHeight) || 40;
  const under = words.offsetHeight + formulaBox.offsetHeight;
  const width = contentWidth(formulaBox);
  if (formulaBox.offsetHeight <= 2.5 * line || width > caption.clientWidth * 0.6) return;
  caption.classList.add('beside');
  // Its column as wide as its typeset pieces reach (a sum's limits overhang
  // the box KaTeX gives it), so the fit never shrinks it below its size.
  formulaBox.style.minWidth = `${Math.ceil(width) + 4}px`;
  if (Math.max(words.offsetHeight, formulaBox.offsetHeight) >= under) {
    caption.classList.remove('beside');
    formulaBox.style.minWidth = '';
  }
}
