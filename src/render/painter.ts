/**
 * The painter: the one object a figure draws with, and the vocabulary it
 * draws in. Its methods say what each primitive draws; the longer ones are
 * drawn by the modules that hold them (strokes, cubicSegments, shapes,
 * handleDrawing, labelPlacer, labelClear, note), and labelOrder holds the
 * order a frame's labels wait in.
 */
import { Ink } from './ink';
import { type ClipRect, circleVisible } from './clip';
import { drawGrid, drawPlotAxes, gridAxesAsInk } from './axes';
import { drawCubicSegments } from './cubicSegments';
import { type HandleStyle, HandleDrawing } from './handleDrawing';
import type { LabelBox, LabelStyle } from './labels';
import { drawLabelClear } from './labelClear';
import { LabelOrder } from './labelOrder';
import { drawScreenLabel } from './labelPlacer';
import { labelWidth } from './labelWidth';
import { type NoteStyle, drawNote } from './note';
import type { Bounds, Projection } from './projection';
import { drawArrow, drawCircle, drawCross, drawOffView, drawRing, fillFacets } from './shapes';
import { ScreenPoints, drawSegments, strokeScreen } from './strokes';
import type { DrawingSurface } from './surface';
import type { Theme } from './theme';

export type P = readonly number[];

export interface StrokeStyle {
  color?: string;
  width?: number;
  dash?: number[];
  alpha?: number;
  /**
   * `curve`: the result the lesson is about (the spline, P(t)'s curve). The
   * presenter can hide it ("predict, then show"); mark the main curve so.
   * `grid`: a background of lines (a pixel grid), which labels may sit on as
   * they sit on the figure's own grid.
   */
  role?: 'curve' | 'grid';
}

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

/** How far outside the figure drawing still reaches (pixels): thick strokes and arrow heads. */
const MARGIN = 64;

/** The least opacity of a filled region's tint on the projector. */
const PROJECTOR_TINT = 0.25;

/**
 * Drawing primitives in lesson (world) coordinates, 2D or 3D: a curve, a
 * polygon, a movable point, a label with lecture subscripts (`P_{1,2}`), an
 * arrow, plot axes. It knows the projection and the theme; it computes no
 * spline. Everything is cut to the visible rectangle first, so the cost of a
 * frame follows the pixels on screen, not the zoom.
 */
export class Painter {
  /** Every label placed this frame, in screen pixels (for overlap checks). */
  readonly labels: LabelBox[] = [];
  /** Every stroke and disc drawn this frame, in screen pixels: where labels must not sit. */
  readonly ink = new Ink();
  /** Labels and the moving point waiting for the figure's ink and handles (see holdLabels). */
  private readonly order = new LabelOrder();
  /** The handles drawn so far, and the accent points and outlines kept of them. */
  private readonly handles = new HandleDrawing();
  /**
   * Points named on the figure that are not handles (screen pixels): the
   * moving point, a constructed point with a name (B₂). A handle's name must
   * be nearer its own point than any of them (P₃'s beside B₂ reads as B₂'s).
   */
  readonly named: [number, number][] = [];
  /** Accent points a handle drawn after them covers (screen pixels): what the tests look for. */
  readonly underHandles: [number, number][] = [];
  readonly clip: ClipRect;
  /** The buffer world points are projected into (see project). */
  private readonly screen = new ScreenPoints();

  constructor(
    readonly ctx: DrawingSurface,
    readonly view: Projection,
    readonly theme: Theme,
    /** What may be drawn: all of it, unless the presenter hid something. */
    readonly show: Readonly<Shown> = SHOW_ALL,
    /** The screen rectangle drawn into: the view and a margin, or an inset's box (render/inset). */
    clip?: ClipRect,
  ) {
    this.clip = clip ?? {
      minX: -MARGIN,
      minY: -MARGIN,
      maxX: view.width + MARGIN,
      maxY: view.height + MARGIN,
    };
  }

  get sizes() {
    return this.theme.sizes;
  }

  color(i: number): string {
    const p = this.theme.palette;
    return p[((i % p.length) + p.length) % p.length];
  }

  /** Is a world point on screen (within `margin` pixels of the figure)? */
  visible(p: P, margin = 0): boolean {
    const [x, y] = this.view.toScreen(p);
    return (
      x >= -margin &&
      y >= -margin &&
      x <= this.view.width + margin &&
      y <= this.view.height + margin
    );
  }

  applyStroke(style: StrokeStyle, fallbackWidth: number, fallbackColor: string): void {
    const c = this.ctx;
    const color = style.color ?? fallbackColor;
    c.strokeStyle = color;
    c.lineWidth = style.width ?? fallbackWidth;
    c.setLineDash(style.dash ?? this.theme.dashOf?.(color) ?? []);
    c.globalAlpha = style.alpha ?? 1;
    c.lineCap = 'round';
    c.lineJoin = 'round';
  }

  clear(): void {
    const c = this.ctx;
    c.save();
    c.globalAlpha = 1;
    c.fillStyle = this.theme.background;
    c.fillRect(0, 0, this.view.width, this.view.height);
    c.restore();
  }

  /** World points as interleaved screen x, y, in a buffer the next projection reuses. */
  project(points: readonly P[]): Float64Array {
    return this.screen.project(this.view, points);
  }

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

  /** The presenter hid what this style draws. */
  hidden(style: StrokeStyle): boolean {
    return style.role === 'curve' && !this.show.curve;
  }

  /** The presenter hid this label (all labels, or those with values). */
  labelHidden(text: string): boolean {
    return !this.show.labels || (!this.show.numbers && NUMBER.test(text));
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

  /**
   * A filled polygon (convex hull, a region), optionally outlined. On the
   * projector a tint is at least a quarter opaque: paler, a weak projector
   * washes it out to the background (#19).
   */
  polygon(points: readonly P[], fill: string, alpha = 0.15, outline?: StrokeStyle): void {
    if (points.length < 3) return;
    const tint = this.theme.projector ? Math.max(alpha, PROJECTOR_TINT) : alpha;
    this.facets([{ points, fill, alpha: tint }]);
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
   * A label at a world point. `text` may carry lecture subscripts:
   * `P_{1,2}` or `P_3` draw the part after `_` lowered and smaller. A point off
   * screen gets no label (it would pile up at the edge).
   */
  label(text: string, p: P, style: LabelStyle = {}): void {
    const [x, y] = this.view.toScreen(p);
    if (!this.onScreen(x, y)) return;
    this.screenLabel(text, x + (style.dx ?? 0), y + (style.dy ?? 0), {
      ...style,
      names: true,
      of: [x, y],
    });
  }

  private onScreen(x: number, y: number): boolean {
    return x >= 0 && y >= 0 && x <= this.view.width && y <= this.view.height;
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
    const [x, y] = this.view.toScreen(p);
    if (!this.onScreen(x, y) || this.labelHidden(text)) return;
    this.placing(() => drawLabelClear(this, text, [x, y], avoid, style));
  }

  /** A label at screen coordinates (pixels): legends, captions. Returns its width. */
  screenLabel(text: string, x: number, y: number, style: LabelStyle = {}): { width: number } {
    if (this.labelHidden(text)) return { width: 0 };
    if (!this.order.holding) return drawScreenLabel(this, text, x, y, style);
    this.order.placing(() => drawScreenLabel(this, text, x, y, style));
    return { width: labelWidth(this, text, style) };
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
