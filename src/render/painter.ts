import type { DrawingSurface } from './surface';
import type { Theme } from './theme';
import { type Bounds, type Viewport, niceStep } from './viewport';

export type P = readonly number[];

export interface StrokeStyle {
  color?: string;
  width?: number;
  dash?: number[];
  alpha?: number;
}

export interface LabelStyle {
  color?: string;
  size?: number;
  /** Offset in pixels from the anchor (screen axes, y down). */
  dx?: number;
  dy?: number;
  align?: CanvasTextAlign;
  baseline?: CanvasTextBaseline;
  bold?: boolean;
  /** Draw a light halo behind the text so it reads over lines. */
  halo?: boolean;
  /** Draw a boxed label (background box with border). */
  box?: boolean;
}

export type HandleState = 'idle' | 'hover' | 'drag' | 'focus';

export interface HandleStyle {
  color?: string;
  shape?: 'circle' | 'square' | 'diamond';
  state?: HandleState;
  radius?: number;
}

/**
 * Drawing primitives in lesson (world) coordinates: a curve, a polygon, a
 * movable point, a label with lecture subscripts (`P_{1,2}`), an arrow, plot
 * axes. It knows the viewport and the theme; it computes no spline.
 */
export class Painter {
  constructor(
    readonly ctx: DrawingSurface,
    readonly view: Viewport,
    readonly theme: Theme,
  ) {}

  get sizes() {
    return this.theme.sizes;
  }

  color(i: number): string {
    const p = this.theme.palette;
    return p[((i % p.length) + p.length) % p.length];
  }

  private applyStroke(style: StrokeStyle, fallbackWidth: number, fallbackColor: string): void {
    const c = this.ctx;
    c.strokeStyle = style.color ?? fallbackColor;
    c.lineWidth = style.width ?? fallbackWidth;
    c.setLineDash(style.dash ?? []);
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

  /** A polyline through world points (a sampled curve, a control polygon). */
  polyline(points: readonly P[], style: StrokeStyle = {}, closed = false): void {
    if (points.length < 2) return;
    const c = this.ctx;
    c.save();
    this.applyStroke(style, this.sizes.curve, this.theme.curve);
    c.beginPath();
    this.tracePolyline(points);
    if (closed) c.closePath();
    c.stroke();
    c.restore();
  }

  /** A polyline from interleaved coordinates [x0, y0, x1, y1, …]: for big samples. */
  polylineFlat(coords: ArrayLike<number>, style: StrokeStyle = {}): void {
    if (coords.length < 4) return;
    const c = this.ctx;
    const v = this.view;
    c.save();
    this.applyStroke(style, this.sizes.curve, this.theme.curve);
    c.beginPath();
    const cx = v.width / 2;
    const cy = v.height / 2;
    for (let i = 0; i < coords.length; i += 2) {
      const x = cx + (coords[i] - v.centerX) * v.scaleX;
      const y = cy - (coords[i + 1] - v.centerY) * v.scaleY;
      if (i === 0) c.moveTo(x, y);
      else c.lineTo(x, y);
    }
    c.stroke();
    c.restore();
  }

  private tracePolyline(points: readonly P[]): void {
    const c = this.ctx;
    points.forEach((p, i) => {
      const [x, y] = this.view.toScreen(p);
      if (i === 0) c.moveTo(x, y);
      else c.lineTo(x, y);
    });
  }

  /**
   * Cubic Bézier segments drawn natively (an affine map keeps a Bézier a
   * Bézier, so the screen path is exact): each segment is 4 control points.
   */
  cubicSegments(segments: readonly (readonly P[])[], style: StrokeStyle = {}): void {
    if (!segments.length) return;
    const c = this.ctx;
    c.save();
    this.applyStroke(style, this.sizes.curve, this.theme.curve);
    c.beginPath();
    segments.forEach((seg, i) => {
      const [p0, p1, p2, p3] = seg.map((p) => this.view.toScreen(p));
      if (i === 0) c.moveTo(p0[0], p0[1]);
      else c.lineTo(p0[0], p0[1]);
      c.bezierCurveTo(p1[0], p1[1], p2[0], p2[1], p3[0], p3[1]);
    });
    c.stroke();
    c.restore();
  }

  segment(a: P, b: P, style: StrokeStyle = {}): void {
    this.polyline([a, b], { width: this.sizes.line, ...style });
  }

  /** A filled polygon (convex hull, a region), optionally outlined. */
  polygon(points: readonly P[], fill: string, alpha = 0.15, outline?: StrokeStyle): void {
    if (points.length < 3) return;
    const c = this.ctx;
    c.save();
    c.globalAlpha = alpha;
    c.fillStyle = fill;
    c.beginPath();
    this.tracePolyline(points);
    c.closePath();
    c.fill();
    c.restore();
    if (outline) this.polyline(points, outline, true);
  }

  /** An arrow from a to b (world), head sized for the theme. */
  arrow(a: P, b: P, style: StrokeStyle = {}): void {
    const [ax, ay] = this.view.toScreen(a);
    const [bx, by] = this.view.toScreen(b);
    const len = Math.hypot(bx - ax, by - ay);
    if (len < 1e-6) return;
    const c = this.ctx;
    const head = Math.min(len * 0.5, 6 + this.sizes.line * 3);
    const ux = (bx - ax) / len;
    const uy = (by - ay) / len;
    c.save();
    this.applyStroke(style, this.sizes.line, this.theme.ink);
    c.beginPath();
    c.moveTo(ax, ay);
    c.lineTo(bx - ux * head * 0.6, by - uy * head * 0.6);
    c.stroke();
    c.setLineDash([]);
    c.fillStyle = style.color ?? this.theme.ink;
    c.beginPath();
    c.moveTo(bx, by);
    c.lineTo(bx - ux * head - uy * head * 0.45, by - uy * head + ux * head * 0.45);
    c.lineTo(bx - ux * head + uy * head * 0.45, by - uy * head - ux * head * 0.45);
    c.closePath();
    c.fill();
    c.restore();
  }

  /** A constructed (not movable) point. */
  dot(p: P, color: string = this.theme.ink, radius: number = this.sizes.point): void {
    const [x, y] = this.view.toScreen(p);
    const c = this.ctx;
    c.save();
    c.fillStyle = color;
    c.beginPath();
    c.arc(x, y, radius, 0, Math.PI * 2);
    c.fill();
    c.restore();
  }

  /** A ring, e.g. a halo whose size shows a weight. */
  ring(p: P, radius: number, style: StrokeStyle = {}, fill?: string, fillAlpha = 0.2): void {
    const [x, y] = this.view.toScreen(p);
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
  }

  /** A movable point: hollow, with a clear hover, drag and keyboard-focus state. */
  handle(p: P, style: HandleStyle = {}): void {
    const [x, y] = this.view.toScreen(p);
    const c = this.ctx;
    const state = style.state ?? 'idle';
    const r =
      (style.radius ?? this.sizes.handle) *
      (state === 'drag' ? 1.25 : state === 'hover' ? 1.15 : 1);
    const stroke = style.color ?? this.theme.handleStroke;
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
    c.fillStyle = state === 'drag' ? stroke : this.theme.handleFill;
    c.strokeStyle = stroke;
    c.lineWidth = Math.max(2, this.sizes.line * 1.2);
    c.beginPath();
    const shape = style.shape ?? 'circle';
    if (shape === 'square') c.rect(x - r, y - r, 2 * r, 2 * r);
    else if (shape === 'diamond') {
      c.moveTo(x, y - r * 1.3);
      c.lineTo(x + r * 1.3, y);
      c.lineTo(x, y + r * 1.3);
      c.lineTo(x - r * 1.3, y);
      c.closePath();
    } else c.arc(x, y, r, 0, Math.PI * 2);
    c.fill();
    c.stroke();
    c.restore();
  }

  /**
   * A label at a world point. `text` may carry lecture subscripts:
   * `P_{1,2}` or `P_3` draw the part after `_` lowered and smaller.
   */
  label(text: string, p: P, style: LabelStyle = {}): void {
    const [x, y] = this.view.toScreen(p);
    this.screenLabel(text, x + (style.dx ?? 0), y + (style.dy ?? 0), style);
  }

  /**
   * A boxed message across the top of the figure, word-wrapped to its width:
   * says on the figure why something is not drawn (coincident points, a
   * parabola that cannot turn back). Returns the y (pixels) below the box, to
   * stack a second note there with `top`.
   */
  note(text: string, style: { color?: string; top?: number } = {}): number {
    const c = this.ctx;
    const size = this.sizes.label;
    const pad = size * 0.5;
    const maxWidth = Math.max(size * 6, this.view.width - 4 * pad);
    c.save();
    c.font = `${size}px ${this.theme.fontFamily}`;
    const lines: string[] = [];
    for (const word of text.split(/\s+/).filter(Boolean)) {
      const last = lines.length ? `${lines[lines.length - 1]} ${word}` : word;
      if (lines.length && c.measureText(last).width <= maxWidth) lines[lines.length - 1] = last;
      else lines.push(word);
    }
    const width = Math.max(...lines.map((line) => c.measureText(line).width), 0);
    const lineHeight = size * 1.3;
    const top = style.top ?? pad;
    c.setLineDash([]);
    c.globalAlpha = 0.94;
    c.fillStyle = this.theme.labelHalo;
    c.fillRect(pad, top, width + 2 * pad, lines.length * lineHeight + pad);
    c.globalAlpha = 1;
    c.strokeStyle = style.color ?? this.theme.accent;
    c.lineWidth = Math.max(2, this.sizes.line);
    c.beginPath();
    c.rect(pad, top, width + 2 * pad, lines.length * lineHeight + pad);
    c.stroke();
    c.fillStyle = this.theme.ink;
    c.textAlign = 'left';
    c.textBaseline = 'middle';
    lines.forEach((line, i) => c.fillText(line, 2 * pad, top + pad / 2 + (i + 0.5) * lineHeight));
    c.restore();
    return top + lines.length * lineHeight + 2 * pad;
  }

  /**
   * Labels beside a plot cursor at x = `at` (world), one per value (e.g. the
   * weights `L_2 = 0.81`), each at its value's height but pushed apart so
   * none covers another.
   */
  cursorLabels(at: number, entries: readonly { y: number; text: string; color: string }[]): void {
    const size = this.sizes.small;
    const gap = size * 1.3;
    const [x] = this.view.toScreen([at, 0]);
    const placed = entries
      .map((entry) => ({ ...entry, sy: this.view.toScreen([at, entry.y])[1] }))
      .sort((a, b) => a.sy - b.sy);
    // Top down, push each label below the one above it; then bottom up, keep
    // them above the axis numbers and the cursor's handle, pushing up in turn.
    const top = size;
    const bottom = this.view.height - size * 3.2;
    for (let i = 0; i < placed.length; i++) {
      placed[i].sy = Math.max(placed[i].sy, i ? placed[i - 1].sy + gap : top);
    }
    for (let i = placed.length - 1; i >= 0; i--) {
      placed[i].sy = Math.min(
        placed[i].sy,
        i < placed.length - 1 ? placed[i + 1].sy - gap : bottom,
      );
    }
    // Near the right edge, write them on the left of the cursor.
    const left = x > this.view.width * 0.75;
    for (const label of placed) {
      // Clear of the cursor's handle, which may sit on the cursor line.
      const offset = this.sizes.handle + 6;
      this.screenLabel(label.text, left ? x - offset : x + offset, label.sy, {
        color: label.color,
        halo: true,
        size,
        align: left ? 'right' : 'left',
      });
    }
  }

  /**
   * A label beside `p` on whichever of four sides (above/below, right/left) lies
   * farthest from the `avoid` points, e.g. the handles around it.
   */
  labelClear(text: string, p: P, avoid: readonly P[], style: LabelStyle = {}): void {
    const [x, y] = this.view.toScreen(p);
    const size = style.size ?? this.sizes.label;
    const width = size * 0.6 * text.length;
    const gap = size * 0.7;
    const candidates: [number, number, CanvasTextAlign][] = [
      [gap, -size, 'left'],
      [gap, size, 'left'],
      [-gap, -size, 'right'],
      [-gap, size, 'right'],
    ];
    const obstacles = avoid.map((q) => this.view.toScreen(q));
    let best = candidates[0];
    let bestClearance = -Infinity;
    for (const candidate of candidates) {
      const [dx, dy, align] = candidate;
      const cx = x + dx + (align === 'left' ? width / 2 : -width / 2);
      const cy = y + dy;
      let clearance = Infinity;
      for (const [ox, oy] of obstacles)
        clearance = Math.min(clearance, Math.hypot(ox - cx, oy - cy));
      if (clearance > bestClearance + 1e-9) {
        bestClearance = clearance;
        best = candidate;
      }
    }
    this.screenLabel(text, x + best[0], y + best[1], { ...style, align: best[2] });
  }

  /** A label at screen coordinates (pixels): legends, captions. */
  screenLabel(text: string, x: number, y: number, style: LabelStyle = {}): { width: number } {
    const c = this.ctx;
    const size = style.size ?? this.sizes.label;
    const runs = splitSubscripts(text);
    const weight = style.bold ? 'bold ' : '';
    const mainFont = `${weight}${size}px ${this.theme.fontFamily}`;
    const subFont = `${weight}${Math.round(size * 0.72)}px ${this.theme.fontFamily}`;
    c.save();
    c.setLineDash([]);
    c.globalAlpha = 1;
    const widths = runs.map((run) => {
      c.font = run.sub ? subFont : mainFont;
      return c.measureText(run.text).width;
    });
    const total = widths.reduce((a, b) => a + b, 0);
    const align = style.align ?? 'left';
    let left =
      align === 'center' ? x - total / 2 : align === 'right' || align === 'end' ? x - total : x;
    const baseline = style.baseline ?? 'middle';
    let middleY = baseline === 'top' ? y + size / 2 : baseline === 'bottom' ? y - size / 2 : y;
    // Keep the whole label inside the figure rather than cut at its edge.
    const margin = 2 + (style.box ? size * 0.35 : 0);
    left = Math.max(margin, Math.min(left, this.view.width - total - margin));
    middleY = Math.max(
      size * 0.7 + margin,
      Math.min(middleY, this.view.height - size * 0.7 - margin),
    );
    if (style.box) {
      const pad = size * 0.35;
      const box: [number, number, number, number] = [
        left - pad,
        middleY - size * 0.62 - pad * 0.4,
        total + 2 * pad,
        size * 1.3 + pad * 0.8,
      ];
      c.fillStyle = this.theme.labelHalo;
      c.globalAlpha = 0.92;
      c.fillRect(...box);
      c.globalAlpha = 1;
      c.strokeStyle = style.color ?? this.theme.ink;
      c.lineWidth = Math.max(1, this.sizes.thin);
      c.beginPath();
      c.rect(...box);
      c.stroke();
    }
    c.textAlign = 'left';
    c.textBaseline = 'middle';
    runs.forEach((run, i) => {
      c.font = run.sub ? subFont : mainFont;
      const textY = run.sub ? middleY + size * 0.3 : middleY;
      if (style.halo && !style.box) {
        // A halo that follows the glyphs, as map labels have: it keeps the text
        // readable over lines without blanking out a rectangle of the figure.
        c.strokeStyle = this.theme.labelHalo;
        c.lineWidth = Math.max(2.5, size * 0.22);
        c.lineJoin = 'round';
        c.globalAlpha = 0.9;
        c.strokeText(run.text, left, textY);
        c.globalAlpha = 1;
      }
      c.fillStyle = style.color ?? this.theme.ink;
      c.fillText(run.text, left, textY);
      left += widths[i];
    });
    c.restore();
    return { width: total };
  }

  /**
   * Light grid with axes through the origin (geometry figures). Grid spacing
   * adapts to the zoom so lines stay about 60 px apart.
   */
  grid(): void {
    const v = this.view;
    const b = v.visibleBounds();
    const step = niceStep(60 / v.scaleX);
    const stepY = niceStep(60 / v.scaleY);
    const c = this.ctx;
    c.save();
    c.strokeStyle = this.theme.grid;
    c.lineWidth = 1;
    c.setLineDash([]);
    c.beginPath();
    for (let x = Math.ceil(b.minX / step) * step; x <= b.maxX; x += step) {
      const [sx] = v.toScreen([x, 0]);
      c.moveTo(Math.round(sx) + 0.5, 0);
      c.lineTo(Math.round(sx) + 0.5, v.height);
    }
    for (let y = Math.ceil(b.minY / stepY) * stepY; y <= b.maxY; y += stepY) {
      const [, sy] = v.toScreen([0, y]);
      c.moveTo(0, Math.round(sy) + 0.5);
      c.lineTo(v.width, Math.round(sy) + 0.5);
    }
    c.stroke();
    c.strokeStyle = this.theme.axis;
    c.beginPath();
    const [ox, oy] = v.toScreen([0, 0]);
    if (ox >= 0 && ox <= v.width) {
      c.moveTo(Math.round(ox) + 0.5, 0);
      c.lineTo(Math.round(ox) + 0.5, v.height);
    }
    if (oy >= 0 && oy <= v.height) {
      c.moveTo(0, Math.round(oy) + 0.5);
      c.lineTo(v.width, Math.round(oy) + 0.5);
    }
    c.stroke();
    c.restore();
  }

  /**
   * Axes for a function plot over `bounds` with tick numbers: the x axis at
   * y = 0 (or the bottom), ticks every `xStep`/`yStep`, and axis names.
   */
  plotAxes(bounds: Bounds, xStep: number, yStep: number, xName = '', yName = ''): void {
    const c = this.ctx;
    const v = this.view;
    const small = this.sizes.small;
    c.save();
    c.setLineDash([]);
    c.strokeStyle = this.theme.grid;
    c.lineWidth = 1;
    c.beginPath();
    for (
      let y = Math.ceil(bounds.minY / yStep - 1e-9) * yStep;
      y <= bounds.maxY + 1e-9;
      y += yStep
    ) {
      const [x0, sy] = v.toScreen([bounds.minX, y]);
      const [x1] = v.toScreen([bounds.maxX, y]);
      c.moveTo(x0, sy);
      c.lineTo(x1, sy);
    }
    for (
      let x = Math.ceil(bounds.minX / xStep - 1e-9) * xStep;
      x <= bounds.maxX + 1e-9;
      x += xStep
    ) {
      const [sx, y0] = v.toScreen([x, bounds.minY]);
      const [, y1] = v.toScreen([x, bounds.maxY]);
      c.moveTo(sx, y0);
      c.lineTo(sx, y1);
    }
    c.stroke();
    c.strokeStyle = this.theme.axis;
    c.lineWidth = Math.max(1, this.sizes.thin);
    const axisY = bounds.minY <= 0 && bounds.maxY >= 0 ? 0 : bounds.minY;
    c.beginPath();
    const [ax0, ay] = v.toScreen([bounds.minX, axisY]);
    const [ax1] = v.toScreen([bounds.maxX, axisY]);
    c.moveTo(ax0, ay);
    c.lineTo(ax1, ay);
    const [lx, ly0] = v.toScreen([bounds.minX, bounds.minY]);
    const [, ly1] = v.toScreen([bounds.minX, bounds.maxY]);
    c.moveTo(lx, ly0);
    c.lineTo(lx, ly1);
    c.stroke();
    c.restore();
    const fmt = (n: number) => String(Number(n.toFixed(6)));
    for (
      let x = Math.ceil(bounds.minX / xStep - 1e-9) * xStep;
      x <= bounds.maxX + 1e-9;
      x += xStep
    ) {
      const [sx, sy] = v.toScreen([x, bounds.minY]);
      this.screenLabel(fmt(x), sx, sy + small * 0.9, {
        size: small,
        align: 'center',
        color: this.theme.muted,
      });
    }
    for (
      let y = Math.ceil(bounds.minY / yStep - 1e-9) * yStep;
      y <= bounds.maxY + 1e-9;
      y += yStep
    ) {
      const [sx, sy] = v.toScreen([bounds.minX, y]);
      this.screenLabel(fmt(y), sx - small * 0.5, sy, {
        size: small,
        align: 'right',
        color: this.theme.muted,
      });
    }
    if (xName) {
      const [sx, sy] = v.toScreen([bounds.maxX, bounds.minY]);
      this.screenLabel(xName, sx, sy + small * 2.1, {
        size: small * 1.1,
        align: 'right',
        color: this.theme.muted,
      });
    }
    if (yName) {
      const [sx, sy] = v.toScreen([bounds.minX, bounds.maxY]);
      this.screenLabel(yName, sx + small * 0.4, sy - small * 0.2, {
        size: small * 1.1,
        color: this.theme.muted,
      });
    }
  }
}

/** Splits `P_{1,2}x_3` into runs of normal and subscript text. */
export function splitSubscripts(text: string): { text: string; sub: boolean }[] {
  const runs: { text: string; sub: boolean }[] = [];
  let i = 0;
  let plain = '';
  while (i < text.length) {
    if (text[i] === '_' && i + 1 < text.length) {
      if (plain) runs.push({ text: plain, sub: false });
      plain = '';
      if (text[i + 1] === '{') {
        const end = text.indexOf('}', i + 2);
        const stop = end < 0 ? text.length : end;
        runs.push({ text: text.slice(i + 2, stop), sub: true });
        i = stop + 1;
      } else {
        runs.push({ text: text[i + 1], sub: true });
        i += 2;
      }
    } else {
      plain += text[i];
      i += 1;
    }
  }
  if (plain) runs.push({ text: plain, sub: false });
  return runs;
}
