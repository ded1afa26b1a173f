import { Ink } from './ink';
import { type ClipRect, circleVisible, clipCubic, clipPolygon, clipPolyline } from './clip';
import { drawGrid, drawPlotAxes, gridAxesAsInk } from './axes';
import { bezierPoint } from '../math';
import type { LabelBox, LabelStyle } from './labels';
import { drawLabelClear } from './labelClear';
import { drawScreenLabel } from './labelPlacer';
import { labelWidth } from './labelWidth';
import { type NoteStyle, drawNote } from './note';
import type { Bounds, Projection } from './projection';
import { type HandleShape, HandleStamper, handlePath } from './handleStamp';
import type { DrawingSurface } from './surface';
import type { Theme } from './theme';

export type { LabelStyle, LabelBox } from './labels';
export { splitSubscripts } from './labels';

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

export type HandleState = 'idle' | 'hover' | 'drag' | 'focus';

export interface HandleStyle {
  color?: string;
  shape?: HandleShape;
  state?: HandleState;
  radius?: number;
  /** The width of its outline (default: a little over a line's). */
  ring?: number;
}

/** How far outside the figure drawing still reaches (pixels): thick strokes and arrow heads. */
const MARGIN = 64;

/**
 * Drawing primitives in lesson (world) coordinates, 2D or 3D: a curve, a
 * polygon, a movable point, a label with lecture subscripts (`P_{1,2}`), an
 * arrow, plot axes. It knows the projection and the theme; it computes no
 * spline. Everything is cut to the visible rectangle first, so the cost of a
 * frame follows the pixels on screen, not the zoom.
 */
/** The least opacity of a filled region's tint on the projector. */
const PROJECTOR_TINT = 0.25;

export class Painter {
  /** Every label placed this frame, in screen pixels (for overlap checks). */
  readonly labels: LabelBox[] = [];
  /** Every stroke and disc drawn this frame, in screen pixels: where labels must not sit. */
  readonly ink = new Ink();
  /** Labels waiting for the figure's ink to be down (see holdLabels), in the order given. */
  private held: (() => void)[] | null = null;
  /** The moving point's drawing, waiting for the handles to be down (see movingPoint). */
  private above: (() => void)[] | null = null;
  /**
   * Large accent discs drawn so far (screen x, y, radius): the point a step is
   * about, drawn larger than a constructed point. A handle drawn over one hides it.
   */
  private accents: [number, number, number][] = [];
  /**
   * Points named on the figure that are not handles (screen pixels): the
   * moving point, a constructed point with a name (B₂). A handle's name must
   * be nearer its own point than any of them (P₃'s beside B₂ reads as B₂'s).
   */
  readonly named: [number, number][] = [];
  /** A mark waits to go on a handle (markOnHandle): the handles' outlines are kept for it. */
  private marksOnHandles = false;
  /** The handles drawn so far, to outline again over a mark on one (markOnHandle). */
  private outlines: {
    x: number;
    y: number;
    r: number;
    stroke: string;
    width: number;
    shape: HandleShape;
  }[] = [];
  /** Accent points a handle drawn after them covers (screen pixels): what the tests look for. */
  readonly underHandles: [number, number][] = [];
  readonly clip: ClipRect;
  private scratch = new Float64Array(256);
  /** Draws handles as stamps on a screen canvas (null elsewhere); found at the first handle. */
  private stamper: HandleStamper | null | undefined;

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

  /** Projects world points into the scratch buffer as interleaved screen x, y. */
  private project(points: readonly P[]): Float64Array {
    const n = points.length;
    if (this.scratch.length < 2 * n) this.scratch = new Float64Array(4 * n);
    const xy = this.scratch;
    for (let i = 0; i < n; i++) {
      const [x, y] = this.view.toScreen(points[i]);
      xy[2 * i] = x;
      xy[2 * i + 1] = y;
    }
    return xy.length === 2 * n ? xy : xy.subarray(0, 2 * n);
  }

  /** A polyline through world points (a sampled curve, a control polygon). */
  polyline(points: readonly P[], style: StrokeStyle = {}, closed = false): void {
    if (points.length < 2) return;
    const path = closed ? [...points, points[0]] : points;
    this.strokeScreen(this.project(path), style);
  }

  /**
   * Separate straight segments in one style, stroked as one path: a sampled
   * surface's hundreds of depth-sorted pieces cost one stroke, not hundreds.
   */
  segments(pairs: readonly (readonly [P, P])[], style: StrokeStyle = {}): void {
    if (!pairs.length || this.hidden(style)) return;
    const c = this.ctx;
    c.save();
    this.applyStroke(style, this.sizes.curve, this.theme.curve);
    c.beginPath();
    let drawn = 0;
    const half = (style.width ?? this.sizes.curve) / 2;
    for (const [a, b] of pairs) {
      const xy = this.project([a, b]);
      drawn += clipPolyline(xy, this.clip, c);
      if (style.role !== 'grid') this.ink.segment(xy[0], xy[1], xy[2], xy[3], half);
    }
    if (drawn > 0) c.stroke();
    c.restore();
  }

  /** The presenter hid what this style draws. */
  hidden(style: StrokeStyle): boolean {
    return style.role === 'curve' && !this.show.curve;
  }

  /** The presenter hid this label (all labels, or those with values). */
  labelHidden(text: string): boolean {
    return !this.show.labels || (!this.show.numbers && NUMBER.test(text));
  }

  private strokeScreen(xy: ArrayLike<number>, style: StrokeStyle): void {
    if (this.hidden(style)) return;
    const c = this.ctx;
    c.save();
    this.applyStroke(style, this.sizes.curve, this.theme.curve);
    c.beginPath();
    if (clipPolyline(xy, this.clip, c) > 0) c.stroke();
    c.restore();
    const from = this.ink.segments;
    if (style.role !== 'grid') this.ink.polyline(xy, (style.width ?? this.sizes.curve) / 2);
    if (style.role === 'curve') this.ink.subject(from);
  }

  /** A polyline from interleaved 2D coordinates [x0, y0, x1, y1, …]: for big samples. */
  polylineFlat(coords: ArrayLike<number>, style: StrokeStyle = {}): void {
    if (coords.length < 4) return;
    const n = coords.length >> 1;
    if (this.scratch.length < 2 * n) this.scratch = new Float64Array(4 * n);
    const xy = this.scratch;
    const point = [0, 0];
    for (let i = 0; i < n; i++) {
      point[0] = coords[2 * i];
      point[1] = coords[2 * i + 1];
      const [x, y] = this.view.toScreen(point);
      xy[2 * i] = x;
      xy[2 * i + 1] = y;
    }
    this.strokeScreen(xy.subarray(0, 2 * n), style);
  }

  /**
   * Cubic Bézier segments, each 4 control points. An affine projection keeps a
   * Bézier a Bézier, so the screen path is exact; under perspective the
   * segments are flattened.
   */
  cubicSegments(segments: readonly (readonly P[])[], style: StrokeStyle = {}): void {
    if (!segments.length || this.hidden(style)) return;
    const c = this.ctx;
    c.save();
    this.applyStroke(style, this.sizes.curve, this.theme.curve);
    c.beginPath();
    let pen: [number, number] | null = null;
    let drawn = false;
    const q = new Array<number>(8);
    const from = this.ink.segments;
    for (const seg of segments) {
      if (!this.view.affine) {
        drawn = this.flattenedCubic(seg, (style.width ?? this.sizes.curve) / 2) || drawn;
        pen = null;
        continue;
      }
      for (let k = 0; k < 4; k++) {
        const [x, y] = this.view.toScreen(seg[k]);
        q[2 * k] = x;
        q[2 * k + 1] = y;
      }
      if (!q.every(Number.isFinite)) {
        pen = null;
        continue;
      }
      const end = clipCubic(q, this.clip, c, pen);
      if (end) drawn = true;
      pen = end;
      this.inkCubic(q, (style.width ?? this.sizes.curve) / 2);
    }
    if (drawn) c.stroke();
    c.restore();
    if (style.role === 'curve') this.ink.subject(from);
  }

  /** A cubic seen through a projection that bends lines (perspective): drawn as 48 chords. */
  private flattenedCubic(seg: readonly P[], half: number): boolean {
    // A segment with a coordinate that is not a number draws nothing (the maths would refuse it).
    if (!seg.every((p) => p.every(Number.isFinite))) return false;
    const samples: P[] = [];
    for (let i = 0; i <= 48; i++) samples.push(bezierPoint(seg, i / 48));
    const xy = this.project(samples);
    this.ink.polyline(xy, half);
    return clipPolyline(xy, this.clip, this.ctx) > 0;
  }

  /** A screen cubic's ink, as 12 chords (within a pixel or so of the curve at figure sizes). */
  private inkCubic(q: readonly number[], half: number): void {
    let [px, py] = [q[0], q[1]];
    for (let i = 1; i <= 12; i++) {
      const t = i / 12;
      const s = 1 - t;
      const [a, b, c, d] = [s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t];
      const x = a * q[0] + b * q[2] + c * q[4] + d * q[6];
      const y = a * q[1] + b * q[3] + c * q[5] + d * q[7];
      this.ink.segment(px, py, x, y, half);
      [px, py] = [x, y];
    }
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

  /**
   * Flat facets (a shaded surface's quads, far to near), each its own fill and
   * opacity, in one save and restore; a facet wholly on the canvas skips the
   * clipper.
   */
  facets(facets: readonly { points: readonly P[]; fill: string; alpha: number }[]): void {
    const c = this.ctx;
    const r = this.clip;
    c.save();
    for (const { points, fill, alpha } of facets) {
      if (points.length < 3) continue;
      let screen: number[][] = points.map((p) => this.view.toScreen(p));
      const inside = screen.every(
        ([x, y]) => x >= r.minX && x <= r.maxX && y >= r.minY && y <= r.maxY,
      );
      if (!inside) screen = clipPolygon(screen, r);
      if (screen.length < 3) continue;
      c.globalAlpha = alpha;
      c.fillStyle = fill;
      c.beginPath();
      screen.forEach(([x, y], i) => (i === 0 ? c.moveTo(x, y) : c.lineTo(x, y)));
      c.closePath();
      c.fill();
    }
    c.restore();
  }

  /** An arrow from a to b (world), head sized for the theme. */
  arrow(a: P, b: P, style: StrokeStyle = {}): void {
    const [ax, ay] = this.view.toScreen(a);
    const [bx, by] = this.view.toScreen(b);
    const len = Math.hypot(bx - ax, by - ay);
    if (!(len > 1e-6) || !Number.isFinite(len)) return;
    const c = this.ctx;
    const head = Math.min(len * 0.5, 6 + this.sizes.line * 3);
    const ux = (bx - ax) / len;
    const uy = (by - ay) / len;
    c.save();
    this.applyStroke(style, this.sizes.line, this.theme.ink);
    c.beginPath();
    const shaft = [ax, ay, bx - ux * head * 0.6, by - uy * head * 0.6];
    const drawn = clipPolyline(shaft, this.clip, c) > 0;
    this.ink.polyline([ax, ay, bx, by], (style.width ?? this.sizes.line) / 2 + head * 0.2);
    if (drawn) c.stroke();
    if (circleVisible(bx, by, head, this.clip)) {
      c.setLineDash([]);
      c.fillStyle = style.color ?? this.theme.ink;
      c.beginPath();
      c.moveTo(bx, by);
      c.lineTo(bx - ux * head - uy * head * 0.45, by - uy * head + ux * head * 0.45);
      c.lineTo(bx - ux * head + uy * head * 0.45, by - uy * head - ux * head * 0.45);
      c.closePath();
      c.fill();
    }
    c.restore();
  }

  /**
   * Where a point the view leaves out lies: an arrow at the figure's edge,
   * pointing at it, named `text` (P(t) carried off by a wild polynomial, say).
   * Draws nothing and returns false for a point on the figure.
   */
  offView(p: P, text: string, color: string): boolean {
    const [x, y] = this.view.toScreen(p);
    if (!Number.isFinite(x) || !Number.isFinite(y) || this.visible(p)) return false;
    const { width, height } = this.view;
    const inset = this.sizes.label * 0.8;
    const tip = [
      Math.min(Math.max(x, inset), width - inset),
      Math.min(Math.max(y, inset), height - inset),
    ];
    const away = Math.hypot(x - tip[0], y - tip[1]);
    const [ux, uy] = [(x - tip[0]) / away, (y - tip[1]) / away];
    const length = this.sizes.label * 2;
    const tail = [tip[0] - ux * length, tip[1] - uy * length];
    const world = (s: readonly number[]) => this.view.toWorld(s, p);
    this.arrow(world(tail), world(tip), { color, width: this.sizes.line * 1.3 });
    this.label(text, world(tail), { color, halo: true, bold: true });
    return true;
  }

  /** A constructed (not movable) point. */
  dot(p: P, color: string = this.theme.ink, radius: number = this.sizes.point): void {
    const [x, y] = this.view.toScreen(p);
    if (!circleVisible(x, y, radius, this.clip)) return;
    this.ink.disc(x, y, radius);
    if (color === this.theme.accent && radius > this.sizes.point) this.accents.push([x, y, radius]);
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
    const [x, y] = this.view.toScreen(p);
    if (!circleVisible(x, y, radius + 4, this.clip)) return;
    const c = this.ctx;
    c.save();
    if (fill) {
      c.globalAlpha = fillAlpha;
      c.fillStyle = fill;
      c.beginPath();
      c.arc(x, y, radius, 0, Math.PI * 2);
      c.fill();
    }
    this.applyStroke(style, this.sizes.thin, this.theme.ink);
    c.beginPath();
    c.arc(x, y, radius, 0, Math.PI * 2);
    c.stroke();
    c.restore();
    this.inkCircle(x, y, radius, (style.width ?? this.sizes.thin) / 2);
  }

  /** A circle's ink: its rim as 32 chords (a label may sit inside a ring). */
  private inkCircle(x: number, y: number, r: number, half: number): void {
    const xy: number[] = [];
    for (let i = 0; i <= 32; i++)
      xy.push(x + r * Math.cos((i * Math.PI) / 16), y + r * Math.sin((i * Math.PI) / 16));
    this.ink.polyline(xy, half);
  }

  /** A cross of half-width `size` pixels, e.g. a guess placed on the figure. */
  cross(p: P, size: number, style: StrokeStyle = {}): void {
    const [x, y] = this.view.toScreen(p);
    if (!circleVisible(x, y, size + 4, this.clip)) return;
    const c = this.ctx;
    c.save();
    this.applyStroke(style, this.sizes.line, this.theme.ink);
    c.beginPath();
    c.moveTo(x - size, y - size);
    c.lineTo(x + size, y + size);
    c.moveTo(x + size, y - size);
    c.lineTo(x - size, y + size);
    c.stroke();
    c.restore();
    this.ink.disc(x, y, size);
  }

  /**
   * A circle of world radius `radius` about `center` (2D), e.g. an osculating
   * circle. A circle far larger than the screen is drawn as the arc that shows.
   */
  circle(center: P, radius: number, style: StrokeStyle = {}): void {
    const [x, y] = this.view.toScreen(center);
    const r = Math.abs(this.view.toScreen([center[0] + radius, center[1]])[0] - x);
    if (!Number.isFinite(r) || !Number.isFinite(x) || !Number.isFinite(y)) return;
    const cx = (this.clip.minX + this.clip.maxX) / 2;
    const cy = (this.clip.minY + this.clip.maxY) / 2;
    const half = Math.hypot(this.clip.maxX - this.clip.minX, this.clip.maxY - this.clip.minY) / 2;
    const d = Math.hypot(cx - x, cy - y);
    // The screen lies wholly inside the circle, or wholly outside it.
    if (d + half < r || d - half > r) return;
    const c = this.ctx;
    c.save();
    this.applyStroke(style, this.sizes.line, this.theme.ink);
    c.beginPath();
    if (r < 4 * half) {
      c.arc(x, y, r, 0, Math.PI * 2);
      this.inkCircle(x, y, r, (style.width ?? this.sizes.line) / 2);
    } else {
      // Only the arc near the screen: its angular width shrinks as the circle grows.
      const toward = Math.atan2(cy - y, cx - x);
      const spread = Math.min(Math.PI, (2 * half) / r);
      const xy: number[] = [];
      for (let i = 0; i <= 64; i++) {
        const a = toward - spread + (2 * spread * i) / 64;
        xy.push(x + r * Math.cos(a), y + r * Math.sin(a));
      }
      clipPolyline(xy, this.clip, c);
      this.ink.polyline(xy, (style.width ?? this.sizes.line) / 2);
    }
    c.stroke();
    c.restore();
  }

  /** A movable point: hollow, with a clear hover, drag and keyboard-focus state. */
  handle(p: P, style: HandleStyle = {}): void {
    const [x, y] = this.view.toScreen(p);
    const state = style.state ?? 'idle';
    const r =
      (style.radius ?? this.sizes.handle) *
      (state === 'drag' ? 1.25 : state === 'hover' ? 1.15 : 1);
    if (!circleVisible(x, y, r * 2, this.clip)) return;
    for (const [ax, ay, ar] of this.accents)
      if (ar < r * 1.5 && Math.hypot(ax - x, ay - y) < r) this.underHandles.push([ax, ay]);
    const width = style.ring ?? Math.max(2, this.sizes.line * 1.2);
    const outer = r * (style.shape === 'diamond' ? 1.3 : 1);
    this.ink.handle(x, y, outer + this.sizes.line, outer + width / 2);
    const c = this.ctx;
    const stroke = style.color ?? this.theme.handleStroke;
    const shape = style.shape ?? 'circle';
    const fill = state === 'drag' ? stroke : this.theme.handleFill;
    // Kept only where a mark waits to go on a handle: road's 500 handles pay nothing.
    if (this.marksOnHandles) this.outlines.push({ x, y, r, stroke, width, shape });
    if (this.stamper === undefined) this.stamper = HandleStamper.for(c);
    // A stamp needs only the alpha saved (a save and restore of the whole state costs more).
    if (this.stamper && state === 'idle') {
      const alpha = c.globalAlpha;
      c.globalAlpha = 1;
      this.stamper.stamp(x, y, { fill, stroke, width, r, shape });
      c.globalAlpha = alpha;
      return;
    }
    c.save();
    c.setLineDash([]);
    c.globalAlpha = 1;
    if (state === 'focus' || state === 'drag' || state === 'hover') {
      c.fillStyle = state === 'focus' ? this.theme.focus : stroke;
      c.globalAlpha = 0.25;
      c.beginPath();
      c.arc(x, y, r * 1.9, 0, Math.PI * 2);
      c.fill();
      c.globalAlpha = 1;
    }
    if (state === 'focus') {
      c.strokeStyle = this.theme.focus;
      c.lineWidth = Math.max(2, this.sizes.line);
      c.beginPath();
      c.arc(x, y, r * 1.6, 0, Math.PI * 2);
      c.stroke();
    }
    if (this.stamper) {
      this.stamper.stamp(x, y, { fill, stroke, width, r, shape });
      c.restore();
      return;
    }
    c.fillStyle = fill;
    c.strokeStyle = stroke;
    c.lineWidth = width;
    c.beginPath();
    handlePath(c, x, y, r, shape);
    c.fill();
    c.stroke();
    c.restore();
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

  /**
   * A boxed message across the top of the figure, word-wrapped to its width:
   * says on the figure why something is not drawn. Returns the y (pixels)
   * below the box, to stack a second note there with `top`.
   */
  note(text: string, style: NoteStyle = {}): number {
    return drawNote(this, text, style);
  }

  /**
   * From now until `placeLabels`, labels wait: they are placed after the
   * figure, its handles and their names are drawn, so each sees all the ink
   * it must keep clear of (a curve drawn after a label used to run through it).
   */
  holdLabels(): void {
    this.held = [];
    this.above = [];
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
    this.marksOnHandles = true;
    this.aboveHandles(() => {
      this.dot(p, color, radius);
      const [x, y] = this.view.toScreen(p);
      const handle = this.outlines.find((o) => Math.hypot(o.x - x, o.y - y) < 0.5);
      if (!handle) return;
      const c = this.ctx;
      c.save();
      c.setLineDash([]);
      c.strokeStyle = handle.stroke;
      c.lineWidth = handle.width;
      c.beginPath();
      handlePath(c, handle.x, handle.y, handle.r, handle.shape);
      c.stroke();
      c.restore();
    });
  }

  /** Draws over the handles (see movingPoint): at once, unless labels are held. */
  aboveHandles(draw: () => void): void {
    if (this.above) this.above.push(draw);
    else draw();
  }

  /** Draws the moving points held back: once the handles are down, before the labels. */
  drawAbove(): void {
    const above = this.above;
    this.above = null;
    above?.forEach((draw) => draw());
  }

  /** Places the labels held back, in the order they were given, on top of the figure. */
  placeLabels(): void {
    this.drawAbove();
    const held = this.held;
    this.held = null;
    held?.forEach((place) => place());
  }

  /** Runs `place` now, or when the held labels are placed (a legend drawn over the figure). */
  placing(place: () => void): void {
    if (this.held) this.held.push(place);
    else place();
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
    if (!this.held) return drawScreenLabel(this, text, x, y, style);
    this.held.push(() => drawScreenLabel(this, text, x, y, style));
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
