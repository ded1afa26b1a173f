/**
 * The ink of one frame: every stroke and disc the painter put on screen, in
 * screen pixels, so that a label can be placed where nothing runs through its
 * letters, and a test can ask of every label whether something does.
 *
 * Segments are kept flat (x1, y1, x2, y2, half width) and found through a
 * coarse grid of cells built only when a label asks, so recording costs a
 * few stores per segment on the hot path and a question costs the cells
 * under one label.
 */
import { clipSegment } from './clip';

/** A screen rectangle. */
export interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

const CELL = 48;
const STRIDE = 5;

export class Ink {
  private segs = new Float64Array(STRIDE * 256);
  private count = 0;
  private readonly discs: number[] = [];
  /**
   * The handles among the discs (x, y, radius with a margin, radius as drawn):
   * what a person drags must never be covered.
   */
  private readonly handleDiscs: number[] = [];
  private readonly areas: Box[] = [];
  /** Lines under the drawing (see rule), four numbers each. */
  private readonly rules: number[] = [];
  /** Cell key → indices of the segments whose box touches the cell. */
  private readonly cells = new Map<number, number[]>();
  /** Segments already in `cells`. */
  private indexed = 0;
  /** Segments too long to index cell by cell (a point a million away): always tested. */
  private readonly long: number[] = [];
  /** Runs of segments [from, to) that draw the figure's subject (a stroke of role 'curve'). */
  readonly subjectRuns: number[] = [];

  /** How many segments were recorded (for tests). */
  get segments(): number {
    return this.count;
  }

  segment(x1: number, y1: number, x2: number, y2: number, halfWidth: number): void {
    if (!(Number.isFinite(x1) && Number.isFinite(y1) && Number.isFinite(x2) && Number.isFinite(y2)))
      return;
    if (this.segs.length < STRIDE * (this.count + 1)) {
      const grown = new Float64Array(this.segs.length * 2);
      grown.set(this.segs);
      this.segs = grown;
    }
    const k = STRIDE * this.count++;
    this.segs[k] = x1;
    this.segs[k + 1] = y1;
    this.segs[k + 2] = x2;
    this.segs[k + 3] = y2;
    this.segs[k + 4] = halfWidth;
  }

  /** The segments recorded since `from` draw the subject: what handles must not bury. */
  subject(from: number): void {
    if (this.count > from) this.subjectRuns.push(from, this.count);
  }

  /** Segment i as [x1, y1, x2, y2, half width] (for tests). */
  segmentAt(i: number): [number, number, number, number, number] {
    const k = STRIDE * i;
    const s = this.segs;
    return [s[k], s[k + 1], s[k + 2], s[k + 3], s[k + 4]];
  }

  /** The handles' discs, flat (x, y, radius with a margin, radius as drawn): a name's rivals, and tests'. */
  get handles(): readonly number[] {
    return this.handleDiscs;
  }

  /** A polyline from interleaved screen coordinates [x0, y0, x1, y1, …]. */
  polyline(xy: ArrayLike<number>, halfWidth: number, closed = false): void {
    const n = xy.length >> 1;
    for (let i = 1; i < n; i++)
      this.segment(xy[2 * i - 2], xy[2 * i - 1], xy[2 * i], xy[2 * i + 1], halfWidth);
    if (closed && n > 2) this.segment(xy[2 * n - 2], xy[2 * n - 1], xy[0], xy[1], halfWidth);
  }

  /**
   * A line drawn under the figure (a grid's axis): no letters may sit on it,
   * but a box (a note, a boxed value) may cover it, as it covers the grid.
   */
  /** The x of every upright rule (a geometry grid's y-axis), in screen pixels. */
  uprightRules(): number[] {
    const r = this.rules;
    const xs: number[] = [];
    for (let i = 0; i < r.length; i += 4) if (r[i] === r[i + 2]) xs.push(r[i]);
    return xs;
  }

  rule(x1: number, y1: number, x2: number, y2: number): void {
    this.rules.push(x1, y1, x2, y2);
  }

  /** A filled panel drawn over the figure (an inset): no label may sit on any of it. */
  area(b: Box): void {
    this.areas.push(b);
  }

  /** A filled or stroked disc (a point, a handle, a ring's outer edge). */
  disc(x: number, y: number, radius: number): void {
    if (Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(radius))
      this.discs.push(x, y, radius);
  }

  /** A handle's disc: ink like any disc, and also what no box may cover. */
  handle(x: number, y: number, radius: number, drawn = radius): void {
    if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(radius))) return;
    this.discs.push(x, y, radius);
    this.handleDiscs.push(x, y, radius, drawn);
  }

  /** How many handles the box covers. */
  handlesUnder(b: Box): number {
    const h = this.handleDiscs;
    let n = 0;
    for (let i = 0; i < h.length; i += 4) if (discMeetsBox(h[i], h[i + 1], h[i + 2], b)) n++;
    return n;
  }

  private key(cx: number, cy: number): number {
    return (cx + 4096) * 8192 + (cy + 4096);
  }

  private index(): void {
    const s = this.segs;
    for (; this.indexed < this.count; this.indexed++) {
      const k = STRIDE * this.indexed;
      const w = s[k + 4];
      // Cells only where a label can be: on a screen of up to 96 cells a side.
      const cell = (v: number) => Math.max(-2, Math.min(96, Math.floor(v / CELL)));
      const x0 = cell(Math.min(s[k], s[k + 2]) - w);
      const x1 = cell(Math.max(s[k], s[k + 2]) + w);
      const y0 = cell(Math.min(s[k + 1], s[k + 3]) - w);
      const y1 = cell(Math.max(s[k + 1], s[k + 3]) + w);
      // A long segment (zoomed far in, a point a million away) is tested
      // directly rather than entered in hundreds of cells.
      if ((x1 - x0 + 1) * (y1 - y0 + 1) > 64) {
        this.long.push(this.indexed);
        continue;
      }
      for (let cx = x0; cx <= x1; cx++)
        for (let cy = y0; cy <= y1; cy++) {
          const key = this.key(cx, cy);
          const list = this.cells.get(key);
          if (list) list.push(this.indexed);
          else this.cells.set(key, [this.indexed]);
        }
    }
  }

  /** Does segment i, thickened by its half width, touch the box? */
  private touches(i: number, b: Box): boolean {
    const s = this.segs;
    const k = STRIDE * i;
    const w = s[k + 4];
    return segmentMeetsBox(s[k], s[k + 1], s[k + 2], s[k + 3], {
      x: b.x - w,
      y: b.y - w,
      width: b.width + 2 * w,
      height: b.height + 2 * w,
    });
  }

  /**
   * Does any stroke or disc of this frame run through the box? A box that
   * is drawn (`covers`: a note, a boxed value) may lie over the rules.
   */
  crosses(b: Box, covers = false): boolean {
    return this.crossing(b, covers) !== null;
  }

  /** The first stroke or disc through the box, said in words (for a test's message), or null. */
  crossing(b: Box, covers = false): string | null {
    this.index();
    const r = this.rules;
    if (!covers)
      for (let i = 0; i < r.length; i += 4)
        if (segmentMeetsBox(r[i], r[i + 1], r[i + 2], r[i + 3], b))
          return `the axis from (${r[i].toFixed(0)}, ${r[i + 1].toFixed(0)}) to (${r[i + 2].toFixed(0)}, ${r[i + 3].toFixed(0)})`;
    for (const a of this.areas)
      if (boxesMeet(a, b)) return `a panel at (${a.x.toFixed(0)}, ${a.y.toFixed(0)})`;
    for (let i = 0; i < this.discs.length; i += 3)
      if (this.discMeets(i, b))
        return `a disc at (${this.discs[i].toFixed(0)}, ${this.discs[i + 1].toFixed(0)})`;
    const s = this.segs;
    for (const i of this.near(b)) {
      if (!this.touches(i, b)) continue;
      const k = STRIDE * i;
      return `a stroke from (${s[k].toFixed(0)}, ${s[k + 1].toFixed(0)}) to (${s[k + 2].toFixed(0)}, ${s[k + 3].toFixed(0)})`;
    }
    return null;
  }

  /**
   * How much ink runs through the box: the discs (points, handles) and the
   * strokes, counted — to choose the corner that hides least when none is free.
   */
  hits(b: Box): { discs: number; strokes: number } {
    this.index();
    let discs = this.areas.filter((a) => boxesMeet(a, b)).length;
    for (let i = 0; i < this.discs.length; i += 3) if (this.discMeets(i, b)) discs++;
    let strokes = 0;
    for (const i of this.near(b)) if (this.touches(i, b)) strokes++;
    return { discs, strokes };
  }

  private discMeets(i: number, b: Box): boolean {
    return discMeetsBox(this.discs[i], this.discs[i + 1], this.discs[i + 2], b);
  }

  /** The segments that may touch the box (those in its cells and the long ones), each once. */
  private *near(b: Box): Generator<number> {
    const seen = new Set<number>();
    for (const i of this.long) {
      seen.add(i);
      yield i;
    }
    const x0 = Math.floor(b.x / CELL);
    const x1 = Math.floor((b.x + b.width) / CELL);
    const y0 = Math.floor(b.y / CELL);
    const y1 = Math.floor((b.y + b.height) / CELL);
    // A box with an infinite side (the widest of no labels) meets no cell:
    // counted cell by cell, -Infinity + 1 never reaches the end.
    if (!Number.isFinite(x0 + x1 + y0 + y1)) return;
    for (let cx = x0; cx <= x1; cx++)
      for (let cy = y0; cy <= y1; cy++)
        for (const i of this.cells.get(this.key(cx, cy)) ?? []) {
          if (seen.has(i)) continue;
          seen.add(i);
          yield i;
        }
  }
}

/** Does the disc of radius r at (x, y) reach into the box? */
function discMeetsBox(x: number, y: number, r: number, b: Box): boolean {
  const dx = Math.max(b.x - x, 0, x - (b.x + b.width));
  const dy = Math.max(b.y - y, 0, y - (b.y + b.height));
  return dx * dx + dy * dy < r * r;
}

/** Does the segment from (ax, ay) to (bx, by) meet the box? */
export function segmentMeetsBox(ax: number, ay: number, bx: number, by: number, b: Box): boolean {
  const rect = { minX: b.x, minY: b.y, maxX: b.x + b.width, maxY: b.y + b.height };
  return clipSegment(ax, ay, bx, by, rect) !== null;
}

/** Do two screen boxes overlap by more than a pixel each way (not merely touch)? */
export function boxesMeet(a: Box, b: Box): boolean {
  const w = Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x);
  const h = Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y);
  return w > 1 && h > 1;
}
