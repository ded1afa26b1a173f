/**
 * A movable point as the painter draws it: hollow, larger while hovered or
 * held, ringed while focused, stamped on a screen canvas; and what the painter
 * keeps of the handles of a frame: the accent points they cover, and their
 * outlines, drawn again over a mark put on one.
 */
import { circleVisible } from './clip';
import { type HandleShape, HandleStamper, handlePath } from './handleStamp';
import type { P, Painter } from './painter';

export type HandleState = 'idle' | 'hover' | 'drag' | 'focus';

export interface HandleStyle {
  color?: string;
  shape?: HandleShape;
  state?: HandleState;
  radius?: number;
  /** The width of its outline (default: a little over a line's). */
  ring?: number;
}

/** One frame's handles: how each is drawn, and what is kept of them. */
export class HandleDrawing {
  /**
   * Large accent discs drawn so far (screen x, y, radius): the point a step is
   * about, drawn larger than a constructed point. A handle drawn over one hides it.
   */
  readonly accents: [number, number, number][] = [];
  /** A mark waits to go on a handle (markOn): the handles' outlines are kept for it. */
  private marksOnHandles = false;
  /** The handles drawn so far, to outline again over a mark on one (markOn). */
  private readonly outlines: {
    x: number;
    y: number;
    r: number;
    stroke: string;
    width: number;
    shape: HandleShape;
  }[] = [];
  /** Draws handles as stamps on a screen canvas (null elsewhere); found at the first handle. */
  private stamper: HandleStamper | null | undefined;

  /** A movable point: hollow, with a clear hover, drag and keyboard-focus state. */
  draw(painter: Painter, p: P, style: HandleStyle = {}): void {
    const [x, y] = painter.view.toScreen(p);
    const state = style.state ?? 'idle';
    const r =
      (style.radius ?? painter.sizes.handle) *
      (state === 'drag' ? 1.25 : state === 'hover' ? 1.15 : 1);
    if (!circleVisible(x, y, r * 2, painter.clip)) return;
    for (const [ax, ay, ar] of this.accents)
      if (ar < r * 1.5 && Math.hypot(ax - x, ay - y) < r) painter.underHandles.push([ax, ay]);
    const width = style.ring ?? Math.max(2, painter.sizes.line * 1.2);
    const outer = r * (style.shape === 'diamond' ? 1.3 : 1);
    painter.ink.handle(x, y, outer + painter.sizes.line, outer + width / 2);
    const c = painter.ctx;
    const stroke = style.color ?? painter.theme.handleStroke;
    const shape = style.shape ?? 'circle';
    const fill = state === 'drag' ? stroke : painter.theme.handleFill;
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
      c.fillStyle = state === 'focus' ? painter.theme.focus : stroke;
      c.globalAlpha = 0.25;
      c.beginPath();
      c.arc(x, y, r * 1.9, 0, Math.PI * 2);
      c.fill();
      c.globalAlpha = 1;
    }
    if (state === 'focus') {
      c.strokeStyle = painter.theme.focus;
      c.lineWidth = Math.max(2, painter.sizes.line);
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
   * A mark on a movable point smaller than its handle (Painter.markOnHandle):
   * a dot over the handle, and the handle's outline drawn again on top of it.
   */
  markOn(painter: Painter, p: P, color: string, radius: number): void {
    this.marksOnHandles = true;
    painter.aboveHandles(() => {
      painter.dot(p, color, radius);
      this.outlineAgain(painter, p);
    });
  }

  /** The outline of the handle drawn at `p` again, over a mark on it. */
  private outlineAgain(painter: Painter, p: P): void {
    const [x, y] = painter.view.toScreen(p);
    const handle = this.outlines.find((o) => Math.hypot(o.x - x, o.y - y) < 0.5);
    if (!handle) return;
    const c = painter.ctx;
    c.save();
    c.setLineDash([]);
    c.strokeStyle = handle.stroke;
    c.lineWidth = handle.width;
    c.beginPath();
    handlePath(c, handle.x, handle.y, handle.r, handle.shape);
    c.stroke();
    c.restore();
  }
}
