/**
 * What the keys act on: the app, the lesson page when one is open (its share
 * of the actions is PageKeys), and the presenter's tools a key switches on and
 * off. The key table that calls them is keymap.ts.
 */

/** What the keys act on: the app, and the lesson page when one is open. */
export interface KeyTarget {
  undo(): void;
  redo(): void;
  /** The clicker's next (+1) or previous (−1): a step, or the next scene. */
  advance(delta: 1 | -1): void;
  /** First or last step of the current scene. */
  stepTo(end: 'first' | 'last'): void;
  togglePlay(): void;
  /** Play slower (−1) or faster (+1). */
  playSpeed(delta: 1 | -1): void;
  fit(): void;
  zoom(factor: number): void;
  /** Turns the first figure in space, in degrees. */
  orbit(yaw: number, pitch: number): void;
  presenter(): void;
  sidePanel(): void;
  /** Presenter view: shows or hides the lecturer's controls (toolbar, slider, steps, tools). */
  lecturerControls(): void;
  /** Poses the next step as a question to the room; the next press reveals it. */
  ask(): void;
  blank(): void;
  /** The screen is blanked: a clicker key only brings it back. */
  readonly blanked: boolean;
  tool(name: PresenterTool): void;
  clearInk(): void;
  dark(): void;
  fullscreen(): void;
  help(): void;
  gallery(): void;
}

/** The keys' actions that belong to the open lesson page (the rest are the app's). */
export type PageKeys = Omit<
  KeyTarget,
  'presenter' | 'dark' | 'fullscreen' | 'help' | 'gallery' | 'blanked'
> & {
  /** The screen is blanked: a clicker key only brings it back. */
  blanked(): boolean;
  unblank(): void;
};

/** Presenter tools that are switched on and off. */
export type PresenterTool =
  'laser' | 'ink' | 'hideCurve' | 'hideNumbers' | 'hideLabels' | 'ghost' | 'trail';
