/**
 * The construction's controls under the figures: the parameter (slider,
 * number field, Play) and the steps (back, status, forward). Each shows the
 * state through `update`, writing to the DOM only what changed.
 */
import { fmt, h, setDisabled, setText } from './dom';
import type { ParameterSpec } from './lesson';
import { nextPlayedValue } from './play';
import { prefersReducedMotion } from './settings';

type Record_ = Record<string, number>;

/** Play speeds, as multiples of one sweep in five seconds. */
const SPEEDS = [0.25, 0.5, 1, 2, 4] as const;

export interface ControlHost<S> {
  get(): S;
  set(next: S, options?: { coalesce?: string; windowMs?: number; record?: boolean }): void;
  /** The value is final for now (Play paused): write the link at once. */
  settle(): void;
}

/**
 * Decimals a parameter's value is shown with: none for a count that moves in
 * whole steps (n = 6, not 6.000: its lesson draws the nearest whole number),
 * three for a parameter on [0, 1] (t = 0.450).
 */
export const decimalsFor = (step: number): number => (Number.isInteger(step) ? 0 : 3);

/** The parameter slider with its number field and Play. */
export class ParameterControl<S> {
  readonly element: HTMLElement;
  readonly slider: HTMLInputElement;
  readonly number: HTMLInputElement;
  readonly play: HTMLButtonElement;
  private playing: { last: number; timer: number } | null = null;
  private shown = NaN;
  /** Play speed, as an index into SPEEDS. */
  private speed = SPEEDS.indexOf(1);
  readonly speedButton: HTMLButtonElement;

  constructor(
    private readonly spec: ParameterSpec<S>,
    private readonly host: ControlHost<S>,
  ) {
    const common = { min: spec.min, max: spec.max, step: spec.step };
    this.slider = h('input', {
      type: 'range',
      ...common,
      'aria-label': spec.label,
      class: 'param-slider',
    });
    this.number = h('input', {
      type: 'number',
      ...common,
      'aria-label': `${spec.label} value`,
      class: 'param-number',
    });
    this.slider.addEventListener('input', () => this.setValue(Number(this.slider.value), 'slider'));
    this.number.addEventListener('change', () =>
      this.setValue(Number(this.number.value), 'number'),
    );
    this.play = h(
      'button',
      {
        type: 'button',
        class: 'play',
        'aria-label': 'Play',
        title: 'Play / pause (K)',
        onclick: () => this.toggle(),
      },
      '▶',
    );
    this.speedButton = h(
      'button',
      {
        type: 'button',
        class: 'play-speed',
        title: 'Play speed (< slower, > faster)',
        onclick: () => this.changeSpeed(this.speed === SPEEDS.length - 1 ? -SPEEDS.length : 1),
      },
      '1×',
    );
    this.speedButton.setAttribute('aria-label', 'Speed 1×');
    this.element = h(
      'div',
      { class: 'param' },
      h('span', { class: 'param-name', 'aria-hidden': 'true' }, spec.label),
      this.slider,
      this.number,
      this.play,
      this.speedButton,
    );
  }

  private value(state: S): number {
    return (state as Record_)[this.spec.key];
  }

  private setValue(value: number, coalesce: string): void {
    if (!Number.isFinite(value)) return;
    const clamped = Math.min(this.spec.max, Math.max(this.spec.min, value));
    this.host.set({ ...this.host.get(), [this.spec.key]: clamped }, { coalesce, windowMs: 1500 });
  }

  /** Moves the parameter by `delta` twentieths of its range (keys on a lesson without steps). */
  nudge(delta: number): void {
    const span = this.spec.max - this.spec.min;
    const v = this.value(this.host.get()) + (delta * span) / 20;
    const clamped = Math.min(this.spec.max, Math.max(this.spec.min, v));
    this.host.set(
      { ...this.host.get(), [this.spec.key]: Number(clamped.toPrecision(12)) },
      { coalesce: 'step-parameter', windowMs: 1500 },
    );
  }

  update(state: S): void {
    const value = this.value(state);
    if (value === this.shown) return;
    this.shown = value;
    if (Number(this.slider.value) !== value) this.slider.value = String(value);
    const shown = fmt(value, decimalsFor(this.spec.step));
    this.slider.setAttribute('aria-valuetext', `${this.spec.label} = ${shown}`);
    if (document.activeElement !== this.number) this.number.value = shown;
  }

  toggle(): void {
    if (this.playing) this.stop();
    else this.start();
  }

  /** One speed slower (−1) or faster (+1), within the list (a large step wraps to the slowest). */
  changeSpeed(delta: number): void {
    this.speed = Math.min(SPEEDS.length - 1, Math.max(0, this.speed + delta));
    const text = `${SPEEDS[this.speed]}×`;
    setText(this.speedButton, text);
    this.speedButton.setAttribute('aria-label', `Speed ${text}`);
  }

  private start(): void {
    const spec = this.spec;
    const span = spec.max - spec.min;
    setText(this.play, '❚❚');
    this.play.setAttribute('aria-label', 'Pause');
    const advance = (amount: number) => {
      const v = nextPlayedValue(this.value(this.host.get()), amount, spec.min, spec.max);
      this.host.set({ ...this.host.get(), [spec.key]: v }, { record: false });
    };
    if (prefersReducedMotion()) {
      // No continuous motion: one calm jump a second.
      this.playing = { last: 0, timer: window.setInterval(() => advance(span / 10), 1000) };
      return;
    }
    this.playing = { last: performance.now(), timer: 0 };
    const tick = (now: number) => {
      if (!this.playing) return;
      const dt = Math.min(0.1, (now - this.playing.last) / 1000);
      this.playing.last = now;
      advance((dt * span * SPEEDS[this.speed]) / 5);
      this.playing.timer = requestAnimationFrame(tick);
    };
    this.playing.timer = requestAnimationFrame(tick);
  }

  stop(): void {
    if (!this.playing) return;
    cancelAnimationFrame(this.playing.timer);
    window.clearInterval(this.playing.timer);
    this.playing = null;
    setText(this.play, '▶');
    this.play.setAttribute('aria-label', 'Play');
    this.host.settle();
  }
}

/**
 * Step back / status / step forward: the clicker's buttons. They walk the
 * lesson's script (steps, then the next scene), exactly as PageDown/PageUp.
 */
export class StepControl {
  readonly element: HTMLElement;
  private readonly back: HTMLButtonElement;
  private readonly forward: HTMLButtonElement;
  private readonly status: HTMLElement;
  private shown = '';
  /** The scene and width the status's height is held for (see `reserve`). */
  private reservedFor = '';
  private reserveFrame = 0;

  constructor(advance: (delta: 1 | -1) => void) {
    this.back = h(
      'button',
      { type: 'button', onclick: () => advance(-1), title: 'Step back (PageUp, ←)' },
      '◀ Back',
    );
    this.forward = h(
      'button',
      { type: 'button', onclick: () => advance(1), title: 'Step forward (PageDown, →, space)' },
      'Next ▶',
    );
    this.status = h('span', { class: 'step-status', 'aria-live': 'polite' });
    this.element = h('div', { class: 'steps' }, this.back, this.status, this.forward);
  }

  /** Shows where the script is: `first`/`last` say whether there is anything before/after. */
  update(text: string, first: boolean, last: boolean, nextLabel = 'Next ▶'): void {
    const key = `${text}/${first}/${last}/${nextLabel}`;
    if (key === this.shown) return;
    this.shown = key;
    setDisabled(this.back, first);
    setDisabled(this.forward, last);
    setText(this.status, text);
    setText(this.forward, nextLabel);
  }

  /**
   * Holds the status at the height of the tallest of a scene's step texts
   * (`texts`, asked for once), so the figures above keep one size as the
   * steps go by (#19). A phone lets the status grow to say a step whole; a
   * wider screen clamps it to two lines, which already keeps one height. `key`
   * says which scene and width the texts are for. All texts are measured in
   * one layout, at once if the status is on the page, else on the next frame.
   */
  reserve(key: string, texts: () => readonly string[]): void {
    if (key === this.reservedFor) return;
    this.reservedFor = key;
    cancelAnimationFrame(this.reserveFrame);
    this.reserveFrame = 0;
    // Not on the page yet (a page still mounting on a busy machine): tried
    // again frame by frame, else the scene kept no room and its figures shrank
    // at its first long step (phone.spec, once in a fresh-clone run).
    let tries = 0;
    const measure = () => {
      this.reserveFrame = 0;
      if (this.reservedFor !== key || this.holdTallest(texts) || ++tries > MEASURE_TRIES) return;
      this.reserveFrame = requestAnimationFrame(measure);
    };
    if (this.status.isConnected) measure();
    else this.reserveFrame = requestAnimationFrame(measure);
  }

  /** A scene's room is still to be measured: the page is not settled. */
  get measuring(): boolean {
    return this.reserveFrame !== 0;
  }

  /**
   * `texts` is asked for only where the status can grow: each derives every
   * step's model. False when the status is not on the page yet, so nothing
   * could be measured; true when it is measured, or has nothing to hold (it
   * is clamped, or hidden as in presenter view).
   */
  private holdTallest(texts: () => readonly string[]): boolean {
    const status = this.status;
    status.style.minHeight = '';
    if (!status.isConnected) return false;
    const style = getComputedStyle(status);
    if (style.maxHeight !== 'none' || !status.getClientRects().length) return true;
    const twin = h('div', { class: 'step-status-twin', 'aria-hidden': 'true' });
    Object.assign(twin.style, {
      width: style.width,
      font: style.font,
      letterSpacing: style.letterSpacing,
      textAlign: style.textAlign,
      overflowWrap: style.overflowWrap,
      wordBreak: style.wordBreak,
      hyphens: style.hyphens,
    });
    for (const text of texts()) twin.append(h('div', {}, text));
    status.after(twin);
    const tallest = Math.max(
      0,
      ...[...twin.children].map((line) => line.getBoundingClientRect().height),
    );
    // Out of the page between measurements: no stale copy of a step's words
    // for a reader, a search or a test to find beside the status.
    twin.remove();
    status.style.minHeight = `${Math.ceil(tallest)}px`;
    return true;
  }
}

/** Frames a scene's room waits for its status to be on the page (two seconds at 60 Hz). */
const MEASURE_TRIES = 120;
