/**
 * The painter: the one object a figure draws with, and the vocabulary it
 * draws in. Its methods say what each primitive draws; the longer ones are
 * drawn by the modules that hold them (strokes, cubicSegments, shapes,
 * handleDrawing, labelling, labelPlacer, labelClear, note), and labelOrder
 * holds the order a frame's labels wait in. What it draws with and records
 * into is its base's (painterBase), which leaves to modules of their own how
 * a stroke looks (strokeStyle), what the presenter lets a figure show
 * (shown), the figure's rectangle on screen (figureRect) and the colours
 * picked from the theme (figureColours).
 */
import { circleVisible } from './clip';
import { drawGrid, drawPlotAxes, gridAxesAsInk } from './axes';
import { drawCubicSegments } from './cubicSegments';
import { regionTint } from './figureColours';
import { type HandleStyle, HandleDrawing } from './handleDrawing';
import type { LabelStyle } from './labels';
import { LabelOrder } from './labelOrder';
import { labelPoint, labelPointClear, labelScreen } from './labelling';
import { type NoteStyle, drawNote } from './note';
import { PainterBase } from './painterBase';
import type { Bounds } from './projection';
import { drawArrow, drawCircle, drawCross, drawOffView, drawRing, fillFacets } from './shapes';
import { drawSegments, strokeScreen } from './strokes';
import type { StrokeStyle } from './strokeStyle';

export { SHOW_ALL, type Shown } from './shown';
export type { StrokeStyle } from './strokeStyle';

export type P = readonly number[];

/**
 * Drawing primitives in lesson (world) coordinates, 2D or 3D: a curve, a
 * polygon, a movable point, a label with lecture subscripts (`P_{1,2}`), an
 * arrow, plot axes. It knows the projection and the theme; it computes no
 * spline. Everything is cut to the visible rectangle first, so the cost of a
 * frame follows the pixels on screen, not the zoom.
 */
export class Painter extends PainterBase {
  /** Labels and the moving point waiting for the figure's ink and handles (see holdLabels). */
  private readonly order = new LabelOrder();
  /** The handles drawn so far, and the accent points and outlines kept of them. */
  private readonly handles = new HandleDrawing();

  /** A polyline through world points (a sampled curve, a control polygon). */
  polyline(points: readonly P[], style: StrokeStyle = {}, closed = false): void {
    if (points.length < 2) return;
    const path = closed ? [...points, points[0]] : points;
    strokeScreen(this, this.project(path), style);
  }

  /** Separate straight segments in one style, stroked as one path (see drawSegments). */
  segments(pairs: readonly (readonly [P, P])[], style: StrokeStyle = {}): void {
    drawSegments(this, pairs, style);
  }

  /** A polyline from interleaved 2D coordinates [x0, y0, x1, y1, …]: for big samples. */
  polylineFlat(coords: ArrayLike<number>, style: StrokeStyle = {}): void {
    if (coords.length < 4) return;
    strokeScreen(this, this.screen.projectFlat(this.view, coords), style);
  }

  /** Cubic Bézier segments, each 4 control points: exact through an affine view (see drawCubicSegments). */
  cubicSegments(segments: readonly (readonly P[])[], style: StrokeStyle = {}): void {
    drawCubicSegments(this, segments, style);
  }

  segment(a: P, b: P, style: StrokeStyle = {}): void {
    this.polyline([a, b], { width: this.sizes.line, ...style });
  }

  /** A filled polygon (convex hull, a region) in its tint (see regionTint), optionally outlined. */
  polygon(points: readonly P[], fill: string, alpha = 0.15, outline?: StrokeStyle): void {
    if (points.length < 3) return;
    this.facets([{ points, fill, alpha: regionTint(this.theme, alpha) }]);
    if (outline) this.polyline(points, outline, true);
  }

  /** Flat facets, each its own fill and opacity, far to near (see fillFacets). */
  facets(facets: readonly { points: readonly P[]; fill: string; alpha: number }[]): void {
    fillFacets(this, facets);
  }

  /** An arrow from a to b (world), head sized for the theme. */
  arrow(a: P, b: P, style: StrokeStyle = {}): void {
    drawArrow(this, a, b, style);
  }

  /** An arrow at the figure's edge pointing at `p` off it, named `text`; false if `p` is on it. */
  offView(p: P, text: string, color: string): boolean {
    return drawOffView(this, p, text, color);
  }

  /** A constructed (not movable) point. */
  dot(p: P, color: string = this.theme.ink, radius: number = this.sizes.point): void {
    const [x, y] = this.view.toScreen(p);
    if (!circleVisible(x, y, radius, this.clip)) return;
    this.ink.disc(x, y, radius);
    if (color === this.theme.accent && radius > this.sizes.point)
      this.handles.accents.push([x, y, radius]);
    const c = this.ctx;
    c.save();
    c.fillStyle = color;
    c.beginPath();
    c.arc(x, y, radius, 0, Math.PI * 2);
    c.fill();
    c.restore();
  }

  /** A ring of `radius` pixels, e.g. a halo whose size shows a weight. */
  ring(p: P, radius: number, style: StrokeStyle = {}, fill?: string, fillAlpha = 0.2): void {
    drawRing(this, p, radius, style, fill, fillAlpha);
  }

  /** A cross of half-width `size` pixels, e.g. a guess placed on the figure. */
  cross(p: P, size: number, style: StrokeStyle = {}): void {
    drawCross(this, p, size, style);
  }

  /** A circle of world radius `radius` about `center` (2D), e.g. an osculating circle. */
  circle(center: P, radius: number, style: StrokeStyle = {}): void {
    drawCircle(this, center, radius, style);
  }

  /** A movable point: hollow, with a clear hover, drag and keyboard-focus state. */
  handle(p: P, style: HandleStyle = {}): void {
    this.handles.draw(this, p, style);
  }

  /**
   * A label at a world point (see labelPoint). `text` may carry lecture
   * subscripts: `P_{1,2}` or `P_3` draw the part after `_` lowered and smaller.
   */
  label(text: string, p: P, style: LabelStyle = {}): void {
    labelPoint(this, text, p, style);
  }

  /** A boxed, word-wrapped message over the figure; returns the y below it, to stack another with `top`. */
  note(text: string, style: NoteStyle = {}): number {
    return drawNote(this, text, style);
  }

  /** From now until `placeLabels`, labels wait for the figure, its handles and their names. */
  holdLabels(): void {
    this.order.hold();
  }

  /**
   * The point a step is about (P(t), P(μ), P(u, v)), in the accent colour and
   * over the handles: at t = 0 it is P₀, and P₀'s handle drawn over it hid it.
   * While labels are held it waits for `drawAbove` (the handles call it).
   */
  movingPoint(p: P, scale = 1.5): void {
    this.namedPoint(p);
    this.aboveHandles(() => this.dot(p, this.theme.accent, this.sizes.point * scale));
  }

  /** A point the figure names that is not a handle: the handles' names keep nearer their own. */
  namedPoint(p: P): [number, number] {
    const at = this.view.toScreen(p) as [number, number];
    this.named.push(at);
    return at;
  }

  /**
   * A mark on a movable point smaller than its handle (a small weight's disc):
   * drawn over the handle, whose outline is drawn again on top, so both are
   * seen (under the handle, its fill hid the mark).
   */
  markOnHandle(p: P, color: string, radius: number): void {
    this.handles.markOn(this, p, color, radius);
  }

  /** Draws over the handles (see movingPoint): at once, unless labels are held. */
  aboveHandles(draw: () => void): void {
    this.order.aboveHandles(draw);
  }

  /** Draws the moving points held back: once the handles are down, before the labels. */
  drawAbove(): void {
    this.order.drawAbove();
  }

  /** Places the labels held back, in the order they were given, on top of the figure. */
  placeLabels(): void {
    this.order.placeLabels();
  }

  /** Runs `place` now, or when the held labels are placed (a legend drawn over the figure). */
  placing(place: () => void): void {
    this.order.placing(place);
  }

  /** A label beside `p` on whichever side lies farthest from the `avoid` points. */
  labelClear(text: string, p: P, avoid: readonly P[], style: LabelStyle = {}): void {
    labelPointClear(this, text, p, avoid, style);
  }

  /** A label at screen coordinates (pixels): legends, captions. Returns its width. */
  screenLabel(text: string, x: number, y: number, style: LabelStyle = {}): { width: number } {
    return labelScreen(this, this.order, text, x, y, style);
  }

  /** Light grid with axes through the origin (2D geometry figures), visible lines only. */
  grid(): void {
    drawGrid(this);
  }

  /** The grid's axes, drawn elsewhere (under the canvas), as lines for labels to keep off. */
  gridAxesAsInk(): void {
    gridAxesAsInk(this);
  }

  /** Axes for a function plot over `bounds` with tick numbers and axis names. */
  plotAxes(bounds: Bounds, xStep: number, yStep: number, xName = '', yName = ''): void {
    drawPlotAxes(this, bounds, xStep, yStep, xName, yName);
  }
}
