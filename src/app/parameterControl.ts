/**
 * The parameter's controls under the figures: its slider, number field, Play
 * and play speed. They show the state through `update`, writing to the DOM
 * only what changed. The steps' controls are in stepControl.ts.
 */
import { h, setText } from './dom';
import { rangeInputs, type RangeInputs } from './rangeControls';
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

/** The parameter slider with its number field and Play. */
export class ParameterControl<S> {
  readonly element: HTMLElement;
  readonly play: HTMLButtonElement;
  private playing: { last: number; timer: number } | null = null;
  private readonly inputs: RangeInputs;
  /** Play speed, as an index into SPEEDS. */
  private speed = SPEEDS.indexOf(1);
  readonly speedButton: HTMLButtonElement;

  constructor(
    private readonly spec: ParameterSpec<S>,
    private readonly host: ControlHost<S>,
  ) {
    const inputs = rangeInputs({ ...spec, name: spec.label, numberField: true }, (value, typed) =>
      this.setValue(value, typed ? 'number' : 'slider'),
    );
    this.inputs = inputs;
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
    this.element = h('div', { class: 'param' }, ...inputs.parts, this.play, this.speedButton);
  }

  private value(state: S): number {
    return (state as Record_)[this.spec.key];
  }

  private setValue(value: number, coalesce: string): void {
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
    this.inputs.show(this.value(state));
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
