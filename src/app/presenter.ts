/**
 * Presenter view and the lecturer's tools: the caption of the current step
 * drawn large with the figure, the side panel folded away, a blank screen, a
 * laser pointer, ink over the figure, and switches for "predict, then show"
 * (hide the curve, the numbers, the labels), a ghost of the figure to compare
 * with, and a trail of the moving point.
 */
import type { Shown } from '../render/painter';
import { CaptionBox } from './captionBox';
import { h, setHidden } from './dom';
import type { PresenterTool } from './keyTarget';
import { PresenterInk } from './presenterInk';

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

export class Presenter {
  /** The caption over the figures: the scene, the step in words, its formula. */
  readonly captionBox = new CaptionBox();
  readonly caption = this.captionBox.element;
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
  private readonly blankCover: HTMLElement;
  private readonly laserDot: HTMLElement;
  private laserTimer = 0;
  private readonly ink: PresenterInk;
  private readonly listening = new AbortController();

  constructor(
    /** The figures' box: ink and the laser live over it. */
    private readonly stage: HTMLElement,
    private readonly onChange: (tool: PresenterTool | 'blank') => void,
    /** Leaves presenter view (its toolbar replaces the app's top bar there). */
    exit: () => void,
  ) {
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
    this.ink = new PresenterInk();
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
    this.captionBox.destroy();
    this.ink.destroy();
  }
}
