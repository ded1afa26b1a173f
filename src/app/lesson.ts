import type { Painter } from '../render/painter';
import type { Theme } from '../render/theme';
import type { Bounds } from '../render/viewport';
import type { HistoryOptions } from './history';
import type { Point2, Schema } from './urlState';

export type { Point2 };

export type LessonGroup = 'interpolation' | 'bezier' | 'splines' | 'surfaces';

export const GROUP_TITLES: Record<LessonGroup, string> = {
  interpolation: 'Interpolation: a curve through points',
  bezier: 'Bézier curves',
  splines: 'Splines',
  surfaces: 'Surfaces and drawing',
};

/** A point the user can move: drawn by the shell on top of the figure. */
export interface Handle {
  /** Stable id, unique within the figure (e.g. `p0`). */
  id: string;
  /** Lecture name with subscripts (`P_0`, `D_1`): drawn next to it and read to screen readers. */
  label: string;
  position: Point2;
  color?: string;
  shape?: 'circle' | 'square' | 'diamond';
  /** Draw the label beside the handle (default true). */
  showLabel?: boolean;
  /** Draw it at half size, so hundreds of points do not hide what they shape (it is picked as usual). */
  small?: boolean;
}

export interface DrawInfo {
  /** Id of what the pointer is over (a handle, or whatever `hoverAt` reported), in any figure. */
  hover: string | null;
  /** Drawing a small gallery thumbnail: skip labels and detail. */
  thumbnail: boolean;
}

/** One canvas of a lesson: a geometric figure (pan and zoom) or a function plot (fixed axes). */
export interface FigureSpec<S> {
  id: string;
  /** Accessible name of the figure. */
  title: string;
  kind: 'geometry' | 'plot';
  /** What "fit view" shows (and plots always show). */
  bounds(state: S): Bounds;
  draw(painter: Painter, state: S, info: DrawInfo): void;
  /** Marks that must stay visible over the handles and their labels (e.g. the arrow just computed). */
  drawOver?(painter: Painter, state: S, info: DrawInfo): void;
  handles?(state: S): Handle[];
  moveHandle?(state: S, id: string, to: Point2): S;
  /** Double-click / long-press on empty space; null if not allowed now. */
  addPoint?(state: S, at: Point2): S | null;
  /** Delete key / context action on a handle; null if not allowed now. */
  removeHandle?(state: S, id: string): S | null;
  /**
   * A handle grabbed away from its dot (e.g. anywhere along a plot's cursor
   * line): the id to drag, or null. Asked only when no handle is within reach.
   */
  pickAt?(state: S, at: Point2, tolerance: number): string | null;
  /** Something other than a handle under the pointer (e.g. a basis curve), for linked highlighting. */
  hoverAt?(state: S, at: Point2, tolerance: number): string | null;
  /** Relative size in the layout (default 1). */
  weight?: number;
}

export type NumberKeys<S> = { [K in keyof S]: S[K] extends number ? K : never }[keyof S] & string;

export interface ParameterSpec<S> {
  key: NumberKeys<S>;
  /** Visible and accessible name of the slider, e.g. `t` or `μ`. */
  label: string;
  min: number;
  max: number;
  step: number;
}

export interface StepsSpec<S> {
  key: NumberKeys<S>;
  /** Steps run 0 … count(state). */
  count(state: S): number;
  /** Says what step k shows, e.g. "Level 2 of 3". */
  describe(state: S, k: number): string;
}

export interface Preset<S> {
  id: string;
  label: string;
  /** The state this preset sets up (from the current one). */
  apply(current: S): S;
}

/** What a lesson's side panel can ask of the shell. */
export interface LessonApi<S> {
  get(): S;
  set(next: S, options?: HistoryOptions & { record?: boolean }): void;
  notice(message: string): void;
  /** Highlight an id across figures (same as hovering it), or null. */
  setHover(id: string | null): void;
  /** The canvas theme, so the panel's colour keys match the figure. */
  theme(): Theme;
}

export interface LessonPanel<S> {
  element: HTMLElement;
  update(state: S, info: DrawInfo): void;
  destroy?(): void;
}

export interface LessonDefinition<S> {
  slug: string;
  title: string;
  /** One line for the gallery. */
  summary: string;
  group: LessonGroup;
  schema: Schema<S>;
  figures: FigureSpec<S>[];
  /** Side by side on a wide screen (default) or stacked. */
  layout?: 'row' | 'column';
  parameter?: ParameterSpec<S>;
  steps?: StepsSpec<S>;
  presets?: Preset<S>[];
  /** Cross-field checks after decoding a link or an edit; returns what it changed, in words. */
  normalize?(state: S): { state: S; issues: string[] };
  panel(api: LessonApi<S>): LessonPanel<S>;
}

/** Keeps the type of S when registering a lesson in a heterogeneous list. */
export function defineLesson<S>(lesson: LessonDefinition<S>): LessonDefinition<S> {
  return lesson;
}

// The registry holds lessons of different state types.
// eslint-disable-next-line @typescript-eslint/no-explicit-any
export type AnyLesson = LessonDefinition<any>;
