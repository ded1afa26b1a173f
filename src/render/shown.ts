/**
 * What the presenter lets a figure show ("predict, then show" hides some):
 * the curve a lesson is about, its labels, and the labels that carry values.
 */
import type { StrokeStyle } from './strokeStyle';

/** What the presenter lets the figure show ("predict, then show" hides some). */
export interface Shown {
  curve: boolean;
  labels: boolean;
  /** Labels with decimal numbers in them (values, coordinates). */
  numbers: boolean;
}

export const SHOW_ALL: Readonly<Shown> = { curve: true, labels: true, numbers: true };

/** A label that carries a value: a decimal number (subscripts like P_{12} are not values). */
const NUMBER = /\d\.\d|\d\s*[=×]|=\s*[−-]?\d/;

/** The presenter hid what this style draws. */
export function strokeHidden(show: Readonly<Shown>, style: StrokeStyle): boolean {
  return style.role === 'curve' && !show.curve;
}

/** The presenter hid this label (all labels, or those with values). */
export function labelHidden(show: Readonly<Shown>, text: string): boolean {
  return !show.labels || (!show.numbers && NUMBER.test(text));
}
