/**
 * Presenter view and the lecturer's tools: the caption of the current step
 * drawn large with the figure, the side panel folded away, a blank screen, a
 * laser pointer, ink over the figure, and switches for "predict, then show"
 * (hide the curve, the numbers, the labels), a ghost of the figure to compare
 * with, and a trail of the moving point.
 */
import type { Shown } from '../render/painter';
import katex from 'katex';
import { markForFit, fitToWidth, contentWidth } from '../render/fit';
import { LiveFormula, filled, typesetSoon } from '../render/formula';
import { sayTex } from '../render/notation';
import { type FormulaParts, slotNumbers } from '../render/formulaParts';
import { h, setHidden, setIndexedText, setText } from './dom';
import type { PresenterTool } from './keymap';

export type ToolState = Record<PresenterTool, boolean>;

const TOOLS: readonly [PresenterTool, string, string][] = [
  ['laser', 'Laser', 'Laser pointer (L)'],
  ['ink', 'Ink', 'Draw over the figure (I; E erases)'],
  ['hideCurve', 'Hide curve', 'Hide the curve: predict, then show (C)'],
  ['hideNumbers', 'Hide numbers', 'Hide the numbers (N)'],
  ['hideLabels', 'Hide labels', 'Hide the labels (A)'],
  ['ghost', 'Ghost', 'Keep the figure as a faint ghost to compare with (O)'],
  ['trail', 'Trail', 'Trace the moving point while the parameter plays (R)'],
];

/** Milliseconds the laser dot stays bright after the pointer stops. */
const LASER_FADE_MS = 1200;

/**
 * The most of the screen's height a caption reserves for its scene: with the
 * figure at three quarters of a 1920 × 1080 screen or more (#19), the rest is
 * the caption's.
 */
const CAPTION_SHARE = 0.24;
/** Pixels a reservation keeps above its tallest measured step. */
const HEADROOM = 10;

export class Presenter {
  /** The caption over the figures: the scene, the step in words, its formula. */
  readonly caption: HTMLElement;
  /** The tool switches (shown under the figures in presenter view). */
  readonly toolbar: HTMLElement;
  readonly tools: ToolState = {
    laser: false,
    ink: false,
    hideCurve: false,
    hideNumbers: false,
    hideLabels: false,
    ghost: false,
    trail: false,
  };
  private readonly buttons = new Map<PresenterTool, HTMLButtonElement>();
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
  private readonly blankCover: HTMLElement;
  private readonly laserDot: HTMLElement;
  private laserTimer = 0;
  private readonly ink: Ink;
  private readonly listening = new AbortController();

  constructor(
    /** The figures' box: ink and the laser live over it. */
    private readonly stage: HTMLElement,
    private readonly onChange: (tool: PresenterTool | 'blank') => void,
    /** Leaves presenter view (its toolbar replaces the app's top bar there). */
    exit: () => void,
  ) {
    this.sceneText = h('span', { class: 'caption-scene' });
    this.stepText = h('span', { class: 'caption-step' });
    this.formulaBox = h('div', { class: 'caption-formula' }, this.formula.element);
    this.caption = h(
      'div',
      { class: 'caption', 'data-caption': '' },
      h('p', { class: 'caption-text' }, this.sceneText, this.stepText),
      this.formulaBox,
    );
    this.toolbar = h(
      'div',
      { class: 'presenter-tools', role: 'toolbar', 'aria-label': 'Presenter tools' },
      h('button', { type: 'button', title: 'Leave presenter view (P)', onclick: exit }, 'Exit'),
      h(
        'button',
        { type: 'button', title: 'Blank the screen (B or .)', onclick: () => this.blank() },
        'Blank',
      ),
      ...TOOLS.map(([tool, label, title]) => {
        const button = h(
          'button',
          { type: 'button', title, 'aria-pressed': 'false', onclick: () => this.toggle(tool) },
          label,
        );
        this.buttons.set(tool, button);
        return button;
      }),
      h(
        'button',
        { type: 'button', title: 'Erase the ink (E)', onclick: () => this.clearInk() },
        'Erase',
      ),
    );
    this.blankCover = h('div', {
      class: 'blank-cover',
      hidden: true,
      'data-blank': '',
      onclick: () => this.unblank(),
    });
    this.laserDot = h('div', { class: 'laser-dot', 'aria-hidden': 'true', hidden: true });
    this.ink = new Ink();
    stage.append(this.ink.canvas, this.laserDot);
    document.body.append(this.blankCover);
    const options = { signal: this.listening.signal, passive: true };
    stage.addEventListener('pointermove', (e) => this.pointAt(e), options);
    stage.addEventListener('pointerdown', (e) => this.pointAt(e), options);
  }

  /** What the figures may draw. */
  shown(): Shown {
    return {
      curve: !this.tools.hideCurve,
      labels: !this.tools.hideLabels,
      numbers: !this.tools.hideNumbers,
    };
  }

  toggle(tool: PresenterTool): void {
    this.tools[tool] = !this.tools[tool];
    this.buttons.get(tool)?.setAttribute('aria-pressed', String(this.tools[tool]));
    if (tool === 'ink') this.ink.active(this.tools.ink);
    if (tool === 'laser') {
      this.stage.classList.toggle('laser-on', this.tools.laser);
      if (!this.tools.laser) setHidden(this.laserDot, true);
    }
    if (tool === 'ink' && this.tools.ink && this.tools.laser) this.toggle('laser');
    if (tool === 'laser' && this.tools.laser && this.tools.ink) this.toggle('ink');
    this.stage.closest('.lesson-page')?.classList.toggle('hide-numbers', this.tools.hideNumbers);
    this.onChange(tool);
  }

  get blanked(): boolean {
    return !this.blankCover.hidden;
  }

  blank(): void {
    if (this.blanked) this.unblank();
    else {
      setHidden(this.blankCover, false);
      this.onChange('blank');
    }
  }

  unblank(): void {
    setHidden(this.blankCover, true);
    this.onChange('blank');
  }

  clearInk(): void {
    this.ink.clear();
  }

  /**
   * The caption of the current step. Its formula is typeset again only when
   * its shape changes: a drag that changes its numbers rewrites their text.
   */
  /** The caption is a question to the room (styled apart, so the room sees it is one). */
  asking(on: boolean): void {
    this.caption.classList.toggle('asking', on);
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
    this.caption.style.minHeight = '';
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
          this.caption.style.minHeight = `${Math.ceil(height)}px`;
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
    this.caption.after(twin);
    twin.style.width = `${this.caption.getBoundingClientRect().width}px`;
    const [scene, words] = twin.querySelectorAll('span');
    setText(scene, step.scene);
    setIndexedText(words, step.step);
    const box = twin.querySelector<HTMLElement>('.twin-formula')!;
    const math = box.firstElementChild as HTMLElement;
    setHidden(box, !step.formula);
    if (step.formula) {
      const tex = typeof step.formula === 'string' ? step.formula : filled(step.formula);
      katex.render(sayTex(tex), math, { throwOnError: false, displayMode: true, strict: false });
      markForFit(math);
      fitToWidth(twin);
    }
    arrange(twin, box);
    const height = twin.getBoundingClientRect().height;
    // Out of the page between measurements: no stale copy of a step's words
    // for a reader, a search or a test to find beside the caption.
    twin.remove();
    return height;
  }

  setCaption(scene: string, step: string, formula: string | FormulaParts | null): void {
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
    // At the new formula's own size: a wide formula before it may have left
    // it shrunk to fit, until the next frame's fit.
    markForFit(this.formula.element);
    fitToWidth(this.caption);
    arrange(this.caption, this.formulaBox);
  }

  private pointAt(e: PointerEvent): void {
    if (!this.tools.laser) return;
    const box = this.stage.getBoundingClientRect();
    this.laserDot.style.transform = `translate(${e.clientX - box.left}px, ${e.clientY - box.top}px)`;
    setHidden(this.laserDot, false);
    this.laserDot.classList.remove('fading');
    window.clearTimeout(this.laserTimer);
    this.laserTimer = window.setTimeout(() => this.laserDot.classList.add('fading'), LASER_FADE_MS);
  }

  destroy(): void {
    this.listening.abort();
    window.clearTimeout(this.laserTimer);
    this.blankCover.remove();
    this.twin.remove();
    this.ink.destroy();
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
function arrange(caption: HTMLElement, formulaBox: HTMLElement): void {
  caption.classList.remove('beside');
  formulaBox.style.minWidth = '';
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

/** Freehand ink over the figures, in CSS pixels of the stage; cleared on a new step. */
class Ink {
  readonly canvas: HTMLCanvasElement;
  private strokes: [number, number][][] = [];
  private current: [number, number][] | null = null;
  private readonly resize: ResizeObserver;
  private readonly listening = new AbortController();

  constructor() {
    this.canvas = h('canvas', { class: 'ink-layer', 'aria-hidden': 'true', 'data-ink': '' });
    const options = { signal: this.listening.signal };
    this.canvas.addEventListener('pointerdown', (e) => this.down(e), options);
    this.canvas.addEventListener('pointermove', (e) => this.move(e), options);
    this.canvas.addEventListener('pointerup', () => (this.current = null), options);
    this.canvas.addEventListener('pointercancel', () => (this.current = null), options);
    this.resize = new ResizeObserver(() => this.redraw());
    this.resize.observe(this.canvas);
    this.showIfUsed();
  }

  /** Ink is on: the layer takes the pointer (else it lets everything through). */
  active(on: boolean): void {
    this.canvas.classList.toggle('inking', on);
    this.showIfUsed();
  }

  /**
   * The layer is there only while ink is on or on the figure: a blank canvas
   * over the stage is copied for the screen on every frame that paints (at
   * 1920×1080 and scale 2, 4.9 million pixels: 4 ms of each drag frame).
   */
  private showIfUsed(): void {
    setHidden(this.canvas, !this.canvas.classList.contains('inking') && this.strokes.length === 0);
  }

  get count(): number {
    return this.strokes.length;
  }

  clear(): void {
    if (this.strokes.length === 0) return;
    this.strokes = [];
    this.current = null;
    this.redraw();
    this.showIfUsed();
  }

  private at(e: PointerEvent): [number, number] {
    const r = this.canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  private down(e: PointerEvent): void {
    this.canvas.setPointerCapture?.(e.pointerId);
    this.current = [this.at(e)];
    this.strokes.push(this.current);
    e.preventDefault();
  }

  private move(e: PointerEvent): void {
    if (!this.current) return;
    const p = this.at(e);
    const last = this.current[this.current.length - 1];
    this.current.push(p);
    const c = this.canvas.getContext('2d');
    if (!c) return;
    this.style(c);
    c.beginPath();
    c.moveTo(last[0], last[1]);
    c.lineTo(p[0], p[1]);
    c.stroke();
  }

  private style(c: CanvasRenderingContext2D): void {
    const dpr = window.devicePixelRatio || 1;
    c.setTransform(dpr, 0, 0, dpr, 0, 0);
    c.strokeStyle = '#e3007d';
    c.lineWidth = 5;
    c.lineCap = 'round';
    c.lineJoin = 'round';
  }

  private redraw(): void {
    const dpr = window.devicePixelRatio || 1;
    const width = Math.round(this.canvas.clientWidth * dpr);
    const height = Math.round(this.canvas.clientHeight * dpr);
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
    }
    const c = this.canvas.getContext('2d');
    if (!c) return;
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.clearRect(0, 0, this.canvas.width, this.canvas.height);
    this.style(c);
    for (const stroke of this.strokes) {
      c.beginPath();
      stroke.forEach(([x, y], i) => (i === 0 ? c.moveTo(x, y) : c.lineTo(x, y)));
      c.stroke();
    }
  }

  destroy(): void {
    this.listening.abort();
    this.resize.disconnect();
  }
}
