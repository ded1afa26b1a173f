/**
 * What a lesson is, for the shell that hosts it. A lesson turns its state into
 * a model once (`derive`), and its figures, handles, hit tests and panel all
 * read that model. See src/lessons/README.md for the way to write one.
 */
import type { Point } from '../math';
import type { CameraSettings } from '../render/orbitCamera';
import type { Painter } from '../render/painter';
import type { Bounds } from '../render/projection';
import type { Letter } from '../render/notation';
import type { Theme } from '../render/theme';
import type { HistoryOptions } from './history';
import type { ExerciseSpec } from '../kit/exercise';
import type { Schema } from './urlState';

export type { Point } from '../math';
export type { LessonGroup } from './meta';

/** A point the user can move: drawn by the shell on top of the figure. */
export interface Handle {
  /** Stable id, unique within the figure (e.g. `p0`). */
  id: string;
  /** Lecture name with subscripts (`P_0`, `D_1`): drawn next to it and read to screen readers. */
  label: string;
  /** Where it is: [x, y] in a plane figure, [x, y, z] in space. */
  position: Point;
  color?: string;
  shape?: 'circle' | 'square' | 'diamond';
  /** Draw the label beside the handle (default true). */
  showLabel?: boolean;
  /** Draw it at half size, so many points do not hide what they shape (it is picked as usual). */
  small?: boolean;
  /**
   * Draw it as a dot narrower than a curve, for one of hundreds of points on
   * the curve they shape (a road through 500 villages): the curve stays seen
   * on either side of it. It is picked as usual, and full size while held.
   */
  dot?: boolean;
  /**
   * For handles stacked on one spot: the world direction in which pulling
   * picks this one (e.g. a repeated knot: [1, 0] for the one on the right).
   * Without it, a pull right or up picks the last of the stack, left or down
   * the first.
   */
  pull?: Point;
}

export interface DrawInfo {
  /** Id of what the pointer is over (a handle, or whatever `hoverAt` reported), in any figure. */
  hover: string | null;
  /** Drawing a small gallery thumbnail: skip labels and detail. */
  thumbnail: boolean;
}

/**
 * How a figure is viewed:
 * - `geometry`: the plane, one scale on both axes, pan and zoom, fit = bounds;
 * - `plot`: a function plot, always shows its bounds, stretched, no pan;
 * - `space`: 3D through an orbit camera (drag to orbit, wheel to zoom);
 * - `drawing`: always shows its bounds at one scale, no pan or zoom.
 */
export type FigureKind = 'geometry' | 'plot' | 'space' | 'drawing';

/** One canvas of a lesson. Every function reads the model derived from the state. */
export interface FigureSpec<S, M = S> {
  id: string;
  /** Accessible name of the figure. */
  title: string;
  kind: FigureKind;
  /** What "fit view" shows (and plots and drawings always show). */
  bounds(model: M): Bounds;
  draw(painter: Painter, model: M, info: DrawInfo): void;
  /**
   * The values the picture is drawn from (by identity), besides the theme,
   * the pointer's hover, the presenter's tools, the canvas's size and view:
   * while they are the same, the canvas is not drawn again (a basis plot
   * while a control point is dragged). Leave it out to draw every frame.
   */
  drawnFrom?(model: M): readonly unknown[];
  /** Marks that must stay visible over the handles and their labels (e.g. the arrow just computed). */
  drawOver?(painter: Painter, model: M, info: DrawInfo): void;
  handles?(model: M): Handle[];
  /** The new state when handle `id` is moved to `to` (constrain it here: to a line, to an order). */
  moveHandle?(state: S, id: string, to: Point, model: M): S;
  /** Double-click / long-press on empty space; null if not allowed now. */
  addPoint?(state: S, at: Point, model: M): S | null;
  /** Delete key / context action on a handle; null if not allowed now. */
  removeHandle?(state: S, id: string, model: M): S | null;
  /**
   * A handle grabbed away from its dot (e.g. anywhere along a plot's cursor
   * line): the id to drag, or null. Asked only when no handle is within reach.
   */
  pickAt?(model: M, at: Point, tolerance: number): string | null;
  /** Something other than a handle under the pointer (e.g. a basis curve), for linked highlighting. */
  hoverAt?(model: M, at: Point, tolerance: number): string | null;
  /**
   * Does the figure write a heading along its top in this state (raster's
   * "Uniform: 14 segments")? Then the fit keeps a band one heading line tall
   * clear above the subject for it: with the handles at the top, it was boxed
   * over the curve. Answer per scene, so the figure keeps one scale through
   * its steps.
   */
  headline?(model: M): boolean;
  /**
   * How many lines of a key (kit/legend.ts) the figure writes at its top,
   * where no corner of its subject is clear for one: the fit keeps a band
   * that tall above the subject, as for a heading (b-splines' two meanings of
   * knots, whose key hid P₂ on a laptop's projector). Answer per scene, the
   * lines of its fullest step's key, so the figure keeps one scale through
   * its steps.
   */
  keyLines?(model: M): number;
  /**
   * How far, in CSS pixels, the figure's marks reach round a point of its
   * subject: the fit keeps at least that much room round the subject, so a
   * mark at its edge is drawn whole (b-splines' two meanings ring a control
   * point at nearly four handles' radius, and on a phone P₀'s and P₆'s rings
   * were cut). Answer per scene, the widest mark of its fullest step, so the
   * figure keeps one scale through its steps.
   */
  marksReach?(model: M, theme: Theme): number;
  /** Relative size in its row or column (default 1). */
  weight?: number;
  /** A fixed height in CSS pixels (a thin strip under another figure). */
  height?: number;
  /** Width over height, kept as the figure is laid out. */
  aspect?: number;
  /**
   * A drawing whose unit may be this many times as long across as up, to fill
   * a short, wide box (a table's cells on a phone); its units stay square
   * otherwise. Plots stretch freely and geometry never.
   */
  widen?: number;
  /** The camera a `space` figure starts with. */
  camera?: CameraSettings;
  /**
   * The moving point whose trail presenter view can draw while the parameter
   * plays (e.g. P(t)); null when there is none now.
   */
  trail?(model: M): Point | null;
}

/**
 * Where the figures go: all in a row or a column, or a tree of rows, columns
 * and grids whose leaves are figure ids. A grid has row and column headings
 * (e.g. three datasets × C⁰, C¹, C²).
 */
export type LayoutNode =
  | string
  | { row: LayoutNode[]; weights?: number[] }
  | { column: LayoutNode[]; weights?: number[] }
  | { grid: { columns: string[]; rows: string[]; cells: string[][] } };

export type NumberKeys<S> = { [K in keyof S]: S[K] extends number ? K : never }[keyof S] & string;

export interface ParameterSpec<S> {
  key: NumberKeys<S>;
  /** Visible and accessible name of the slider, e.g. `t` or `μ`. */
  label: string;
  min: number;
  max: number;
  step: number;
}

/**
 * The construction a clicker walks through, one step at a time. Step 0 shows
 * little (the given points); each step adds one thing; the last shows it all.
 */
export interface StepsSpec<S, M = S> {
  /** The state's field (an `int`) that holds the step. */
  key: NumberKeys<S>;
  /** Steps run 0 … count(state). Long constructions step in chunks (tens of steps, not hundreds). */
  count(state: S): number;
  /**
   * The caption of step k: what this step shows, in one short sentence
   * ("Level 2: the points P_{2,i} between the P_{1,i}"). The step status and
   * presenter view show it; plain words and Unicode, no TeX.
   */
  describe(state: S, k: number): string;
  /**
   * The formula of the current step with its numbers (TeX), drawn large under
   * the caption in presenter view; null when the step has none. The shell
   * makes its decimal numbers live (`slotNumbers`): a drag that changes only
   * numbers rewrites their text, it does not typeset again.
   */
  formula?(model: M, state: S): string | null;
}

/**
 * A scene of the lesson's script: a figure of the lecture (a preset), in
 * teaching order. The clicker opens the next scene after the last step of
 * this one; a scene always opens at step 0.
 */
export interface Scene<S> {
  /** Stable id, in the link as `scene=<id>`. */
  id: string;
  label: string;
  /** The state this scene sets up (from the current one). The shell then sets the step to 0. */
  apply(current: S): S;
}

/** Earlier name of a scene. */
export type Preset<S> = Scene<S>;

/** What a lesson's side panel can ask of the shell. */
export interface LessonApi<S, M = S> {
  get(): S;
  /** The model of the current state (derived once, shared with the figures). */
  model(): M;
  set(next: S, options?: HistoryOptions & { record?: boolean }): void;
  notice(message: string): void;
  /** Highlight an id across figures (same as hovering it), or null. */
  setHover(id: string | null): void;
  /** The canvas theme, so the panel's colour keys match the figure. */
  theme(): Theme;
}

export interface LessonPanel<S, M = S> {
  element: HTMLElement;
  /** Called once per new state (never for a pan, a zoom or a hover): change only what changed. */
  update(model: M, state: S): void;
  /** The hovered id changed (optional: most panels ignore hover). */
  hover?(id: string | null): void;
  destroy?(): void;
}

export interface LessonDefinition<S, M = S> {
  slug: string;
  schema: Schema<S>;
  /**
   * The state's model: everything spline-related the figures and the panel
   * show, computed once per state (the shell memoises it per state object,
   * and states are never mutated).
   */
  derive(state: S): M;
  figures: FigureSpec<S, M>[];
  /** Side by side on a wide screen (default), stacked, or a tree of rows, columns and grids. */
  layout?: 'row' | 'column' | LayoutNode;
  /**
   * The same figures arranged for a tall subject (a plot beside the curve
   * rather than under it): presenter view takes it for a scene whose
   * subject it draws clearly larger (see tallLayout.ts).
   */
  tallLayout?: LayoutNode;
  parameter?: ParameterSpec<S>;
  /**
   * The letter the lesson's text writes its curve parameter with ('t' or
   * 'mu'); the reader's chosen letter replaces it in everything shown. Absent
   * for a lesson whose letters are all its own (a surface's u and v).
   */
  letter?: Letter;
  /** The construction's steps (the clicker's unit). */
  steps?: StepsSpec<S, M>;
  /** The lesson's script: its scenes in teaching order (the first is what the lesson opens with). */
  scenes?: Scene<S>[];
  /** Cross-field checks after decoding a link or an edit; returns what it changed, in words. */
  normalize?(state: S): { state: S; issues: string[] };
  /**
   * The ids of the figures this state's scene shows (the others are hidden
   * and not drawn); null or absent: all of them.
   */
  figuresShown?(state: S): readonly string[] | null;
  /** The id of the scene a state is in, where a field of the state says so (an exercise opens there). */
  sceneOf?(state: S): string | undefined;
  panel(api: LessonApi<S, M>): LessonPanel<S, M>;
  /**
   * The tables a handout prints under a scene's last frame (de Casteljau's
   * points, the Thomas sweep, the Cox–de Boor triangle, the net): the same
   * numbers the panel shows, as plain text.
   */
  tables?(model: M, state: S): HandoutTable[];
  /** The lesson's exercises (see kit/exercise.ts), in the order the practice card lists them. */
  exercises?: readonly ExerciseSpec<S>[];
}

/** A table of a handout: a title, column headings, and rows of plain-text cells. */
export interface HandoutTable {
  title: string;
  columns: string[];
  rows: string[][];
}

/** Keeps the types of S and M when registering a lesson in a heterogeneous list. */
export function defineLesson<S, M = S>(lesson: LessonDefinition<S, M>): LessonDefinition<S, M> {
  return lesson;
}

// The shell hosts lessons of different state and model types.
// eslint-disable-next-line @typescript-eslint/no-explicit-any
export type AnyLesson = LessonDefinition<any, any>;
