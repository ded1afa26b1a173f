/**
 * A point's handle on a screen canvas, as a stamp: drawn once, copied to
 * every point (see HandleStamper); and the outline every handle is drawn
 * with, stamp or path.
 */
import type { DrawingSurface } from './surface';

/** The outline of a handle. */
export type HandleShape = 'circle' | 'square' | 'diamond';

/** What a handle looks like: a stamp is drawn once for each. */
export interface HandleLook {
  readonly fill: string;
  readonly stroke: string;
  readonly width: number;
  readonly r: number;
  readonly shape: HandleShape;
}

/** A handle's pixels, copied to every point with that look. */
type Stamp = HTMLCanvasElement | ImageBitmap;
const stamps = new Map<string, Stamp>();
const MAX_STAMPS = 256;
/** How many times the stamps were let go: a stamper's last stamp is of this generation or stale. */
let generation = 0;

/**
 * Lets every stamp go (the cache is full: a figure's looks changed many
 * times, as a theme or a scale did): a bitmap's pixels are freed now, not
 * whenever the collector comes, and no stamper copies one after it is closed.
 */
function releaseStamps(): void {
  for (const stamp of stamps.values()) if ('close' in stamp) stamp.close();
  stamps.clear();
  generation++;
}

/**
 * On a screen canvas, a handle is a stamp: its disc and ring drawn once into a
 * small canvas at the device's scale, then copied wherever a handle goes (to
 * the nearest device pixel). Drawn as paths, the 500 villages of the road's
 * valley were 1,000 fills and strokes to rasterise on every drag frame, 16.5
 * ms of a 33 ms frame. Elsewhere (an SVG export, a test's recording) handles
 * are paths, as before.
 */
export class HandleStamper {
  /** The look last stamped, and its stamp: most handles of a figure share one. */
  private lastLook: HandleLook | null = null;
  private last: Stamp | null = null;
  private lastGeneration = generation;

  private constructor(
    private readonly c: CanvasRenderingContext2D,
    /** Device pixels per CSS pixel, and the shift, of the canvas's transform. */
    private readonly scale: number,
    private readonly e: number,
    private readonly f: number,
  ) {}

  /** A stamper for `c` if it is a screen canvas with a plain scale (the figure's device pixels). */
  static for(c: DrawingSurface): HandleStamper | null {
    if (typeof CanvasRenderingContext2D === 'undefined' || !(c instanceof CanvasRenderingContext2D))
      return null;
    const m = c.getTransform();
    if (m.b !== 0 || m.c !== 0 || m.a !== m.d || m.a <= 0) return null;
    return new HandleStamper(c, m.a, m.e, m.f);
  }

  /** Copies the stamp of `look` centred at (x, y) (CSS pixels), snapped to a device pixel. */
  stamp(x: number, y: number, look: HandleLook): void {
    let stamp = this.last;
    if (
      !stamp ||
      !this.lastLook ||
      this.lastGeneration !== generation ||
      !sameLook(look, this.lastLook)
    ) {
      const key = `${look.fill}|${look.stroke}|${look.width}|${look.r}|${look.shape}|${this.scale}`;
      stamp = this.last = stamps.get(key) ?? this.draw(key, look);
      this.lastLook = look;
      this.lastGeneration = generation;
    }
    const { scale, e, f } = this;
    const half = stamp.width / 2;
    // The stamp's pixels land on device pixels: no resampling, no blur.
    const left = (Math.round(scale * x + e) - half - e) / scale;
    const top = (Math.round(scale * y + f) - half - f) / scale;
    this.c.drawImage(stamp, left, top, stamp.width / scale, stamp.height / scale);
  }

  private draw(key: string, look: HandleLook): Stamp {
    if (stamps.size >= MAX_STAMPS) releaseStamps();
    const reach = look.r * (look.shape === 'diamond' ? 1.3 : look.shape === 'square' ? 1.42 : 1);
    const half = Math.ceil((reach + look.width) * this.scale) + 1;
    const stamp = paintStamp(2 * half, (s) => {
      s.setTransform(this.scale, 0, 0, this.scale, half, half);
      s.fillStyle = look.fill;
      s.strokeStyle = look.stroke;
      s.lineWidth = look.width;
      s.beginPath();
      handlePath(s, 0, 0, look.r, look.shape);
      s.fill();
      s.stroke();
    });
    stamps.set(key, stamp);
    return stamp;
  }
}

/**
 * A square stamp of `size` device pixels, painted by `paint`: an ImageBitmap
 * where there is OffscreenCanvas, else a canvas. Chromium snapshots a canvas
 * at every drawImage from it, and a bitmap not at all: the valley's 500
 * villages were 500 snapshots a drag frame, 2.0 ms of script (0.7 ms as
 * bitmaps).
 */
function paintStamp(
  size: number,
  paint: (s: CanvasRenderingContext2D | OffscreenCanvasRenderingContext2D) => void,
): Stamp {
  if (typeof OffscreenCanvas !== 'undefined') {
    const offscreen = new OffscreenCanvas(size, size);
    const s = offscreen.getContext('2d');
    if (s) paint(s);
    return offscreen.transferToImageBitmap();
  }
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  const s = canvas.getContext('2d');
  if (s) paint(s);
  return canvas;
}

/** Whether two looks draw the same stamp. */
const sameLook = (a: HandleLook, b: HandleLook): boolean =>
  a === b ||
  (a.fill === b.fill &&
    a.stroke === b.stroke &&
    a.width === b.width &&
    a.r === b.r &&
    a.shape === b.shape);

/** Adds one handle's outline to the current path. */
export function handlePath(
  c: DrawingSurface | CanvasRenderingContext2D,
  x: number,
  y: number,
  r: number,
  shape: HandleShape,
): void {
  if (shape === 'square') c.rect(x - r, y - r, 2 * r, 2 * r);
  else if (shape === 'diamond') {
    c.moveTo(x, y - r * 1.3);
    c.lineTo(x + r * 1.3, y);
    c.lineTo(x, y + r * 1.3);
    c.lineTo(x - r * 1.3, y);
    c.closePath();
  } else c.arc(x, y, r, 0, Math.PI * 2);
}
