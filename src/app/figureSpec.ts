/**
 * A lesson's figure, for the shell that draws it: what it shows and how it is
 * fitted (FigureSpec), the points a user moves on it (Handle), and what a
 * frame's drawing is told (DrawInfo). A lesson's definition is lesson.ts.
 */
import type { Point } from '../math';
import type { CameraSettings } from '../render/orbitCamera';
import type { Painter } from '../render/painter';
import type { Bounds } from '../render/projection';
import type { Theme } from '../render/theme';
import type { CursorValues } from '../kit/valueRows';

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
   * The values a plot writes at its cursor (kit/cursorValues valueColumn):
   * how many and the widest. The fit keeps room above the plot for the rows
   * they take at its width, so they stand over no curve (in presenter view's
   * short strips they were boxed over the very peaks of L₁ and H₁, and in
   * its tall strip beside the curve, four to a row's one, over H₁). Answer
   * per scene, its fullest step, so the plot keeps one size through its steps.
   */
  cursorValues?(model: M): CursorValues;
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
  /**
   * Room kept at a drawing's edges for its handles' names, in label heights
   * (default 1.6). A drawing whose bounds hold its own names (the surface's
   * heat map, its factors round it) gives it to its subject instead.
   */
  edgeRoom?: number;
  /** The camera a `space` figure starts with. */
  camera?: CameraSettings;
  /**
   * The moving point whose trail presenter view can draw while the parameter
   * plays (e.g. P(t)); null when there is none now.
   */
  trail?(model: M): Point | null;
}
