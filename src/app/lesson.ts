/**
 * What a lesson is, for the shell that hosts it. A lesson turns its state into
 * a model once (`derive`), and its figures, handles, hit tests and panel all
 * read that model. See src/lessons/README.md for the way to write one.
 */
import type { Letter } from '../render/notation';
import type { Theme } from '../render/theme';
import type { HistoryOptions } from './history';
import type { ExerciseSpec } from '../kit/exercise';
import type { Schema } from './urlState';
import type { FigureSpec } from './figureSpec';

export type { Point } from '../math';
export type { LessonGroup } from './meta';
export type { DrawInfo, FigureKind, FigureSpec, Handle } from './figureSpec';

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
