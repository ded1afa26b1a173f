/**
 * Range controls: a slider with its number field, built once for the
 * parameter's row (parameterControl.ts) and the side panels' sliders.
 */
import { fmt, h, setText } from './dom';
import { freeBox } from '../render/liveBoxes';
import type { Control, StateApi } from './panelControls';

/**
 * Decimals a value is shown with: none for a count that moves in whole steps
 * (n = 6, not 6.000: its lesson draws the nearest whole number), three for a
 * parameter on [0, 1] (t = 0.450).
 */
export const decimalsFor = (step: number): number => (Number.isInteger(step) ? 0 : 3);

export interface RangeSpec {
  /** The slider's accessible name; a number field's is `<label> value`. */
  label: string;
  /** The name written before the slider (screen readers hear `label` instead), or none. */
  name?: string;
  min: number;
  max: number;
  step: number;
  /** A number field beside the slider, to type a value. */
  numberField?: boolean;
}

/** A slider and its number field, built once for the parameter's row and the panels' sliders. */
export interface RangeInputs {
  readonly slider: HTMLInputElement;
  readonly number: HTMLInputElement | null;
  /** The name, then each field in a slot of its own, to put in a row. */
  readonly parts: HTMLElement[];
  /** Shows a value (and a new top of the range), writing only what changed. */
  show(value: number, top?: number): void;
}

/**
 * Each field sits in a slot of its own (see .param-slot in styles.css), so a
 * drag that moves the thumb and writes the number lays out the two fields,
 * not the page round them. `onValue` hears a finite value, and whether it was
 * typed.
 */
export function rangeInputs(
  spec: RangeSpec,
  onValue: (value: number, typed: boolean) => void,
): RangeInputs {
  const range = { min: spec.min, max: spec.max, step: spec.step };
  const slider = h('input', {
    type: 'range',
    ...range,
    'aria-label': spec.label,
    class: 'param-slider',
  });
  const number = spec.numberField
    ? h('input', {
        type: 'number',
        ...range,
        'aria-label': `${spec.label} value`,
        class: 'param-number',
      })
    : null;
  const heard = (field: HTMLInputElement, typed: boolean) => () => {
    const value = Number(field.value);
    if (Number.isFinite(value)) onValue(value, typed);
  };
  slider.addEventListener('input', heard(slider, false));
  number?.addEventListener('change', heard(number, true));
  const decimals = decimalsFor(spec.step);
  let shown = NaN;
  let shownTop = spec.max;
  return {
    slider,
    number,
    parts: [
      ...(spec.name ? [h('span', { class: 'param-name', 'aria-hidden': 'true' }, spec.name)] : []),
      h('span', { class: 'param-slot param-slot-slider' }, slider),
      ...(number ? [h('span', { class: 'param-slot' }, number)] : []),
    ],
    show(value, top = spec.max) {
      if (top !== shownTop) {
        shownTop = top;
        slider.max = String(top);
        if (number) number.max = String(top);
        shown = NaN;
      }
      if (value === shown) return;
      shown = value;
      if (Number(slider.value) !== value) slider.value = String(value);
      const text = fmt(value, decimals);
      slider.setAttribute('aria-valuetext', `${spec.label} = ${text}`);
      if (number && document.activeElement !== number) number.value = text;
    },
  };
}

export interface RangeFieldOptions<S> extends RangeSpec {
  /** The top of the range when the state sets it (p̄ runs to the road's last village). */
  maxOf?(state: S): number;
  get(state: S): number;
  set(state: S, value: number): S;
  /** Moves of one drag are one edit in the history under this name (typed values under `<name>-typed`). */
  coalesce: string;
  /** Words after the slider, given to `update` (the value and what it means): a live value in a box of its own. */
  readout?: boolean;
  /** A class for the row, for a lesson's own layout. */
  class?: string;
  /** The readout's least width in ems, so that rows of sliders one under another are as long. */
  readoutEm?: number;
}

/** A range control of the panel: its slider, and its number field when it has one. */
export interface RangeField<S> extends Control<S> {
  /** Shows the state, and `readout` after the slider. */
  update(state: S, readout?: string): void;
  readonly slider: HTMLInputElement;
  readonly number: HTMLInputElement | null;
}

/**
 * A slider bound to a number of the state, built as the parameter's own row
 * is (rangeInputs), with its readout in a box of its own (render/liveBoxes.ts):
 * a drag lays out the fields and the readout, not the panel round them.
 */
export function rangeField<S>(api: StateApi<S>, options: RangeFieldOptions<S>): RangeField<S> {
  const inputs = rangeInputs(options, (value, typed) => {
    const s = api.get();
    const top = options.maxOf?.(s) ?? options.max;
    api.set(options.set(s, Math.min(top, Math.max(options.min, value))), {
      coalesce: typed ? `${options.coalesce}-typed` : options.coalesce,
      windowMs: 1500,
    });
  });
  const readout = options.readout ? freeBox(h('span', { class: 'range-readout' })) : null;
  if (readout && options.readoutEm) readout.style.minWidth = `${options.readoutEm}em`;
  const element = h(
    'div',
    { class: options.class ? `range-field ${options.class}` : 'range-field' },
    ...inputs.parts,
    readout,
  );
  return {
    element,
    slider: inputs.slider,
    number: inputs.number,
    update(state, text) {
      inputs.show(options.get(state), options.maxOf?.(state) ?? options.max);
      if (readout && text !== undefined) setText(readout, text);
    },
  };
}
