/**
 * How to do things with the device in hand: a lesson's instructions are
 * written with these phrases, so a phone's say "press and hold" and a
 * laptop's say "double-click". Read once, when a panel is built (a device
 * does not change its pointer while a page is open).
 */

/** Is the main pointer a finger? */
export const touchFirst = (): boolean =>
  typeof window !== 'undefined' && (window.matchMedia?.('(pointer: coarse)').matches ?? false);

export interface Gestures {
  /** Moving a point: "drag it with a finger" / "drag it, or Tab to it and use the arrow keys". */
  move: string;
  /** Adding a point on empty space. */
  add: string;
  /** Removing a point. */
  remove: string;
  /** Showing what a thing is tied to: "tap" / "hover over". */
  point: string;
  /** Turning a figure in space. */
  orbit: string;
  /** Zooming a figure. */
  zoom: string;
}

const TOUCH: Gestures = {
  move: 'drag it with a finger',
  add: 'press and hold empty space',
  remove: 'tap a point, then its Delete button',
  point: 'tap',
  orbit: 'turn it with two fingers',
  zoom: 'pinch',
};

const POINTER: Gestures = {
  move: 'drag it, or Tab to it and use the arrow keys',
  add: 'double-click empty space',
  remove: 'right-click a point (or press Delete on a focused one)',
  point: 'hover over',
  orbit: 'drag empty space to turn it',
  zoom: 'use the wheel or pinch',
};

/** The phrases for this device (or for `touch` when given: the tests ask for both). */
export function gestures(touch: boolean = touchFirst()): Gestures {
  return touch ? TOUCH : POINTER;
}

/** A sentence's first letter in capitals (phrases start a sentence as often as not). */
export const capital = (text: string) => text.charAt(0).toUpperCase() + text.slice(1);
