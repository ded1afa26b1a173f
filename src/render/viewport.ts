/**
 * The 2D projection: lesson coordinates (y up) to CSS pixels (y down).
 * Device pixels are the canvas's business; everything a 2D figure draws goes
 * through here.
 */
import { type Bounds, type Projection, readNumbers, viewNumber } from './projection';

export type { Bounds } from './projection';
export { boundsOf, unionBounds, niceStep } from './projection';

/** Zoom limits in pixels per unit: from a continent to a hair, and no further. */
const MIN_SCALE = 1e-6;
const MAX_SCALE = 1e9;

export class Viewport implements Projection {
  readonly dimension = 2;
  readonly affine = true;
  /** World coordinates at the centre of the view. */
  centerX = 0;
  centerY = 0;
  /** Pixels per world unit, horizontally and vertically. */
  scaleX = 100;
  scaleY = 100;
  /**
   * Rows of values at its cursor the fit kept room for above a plot (see
   * kit/cursorValues.ts; its padding may hold them already), 0 where none.
   */
  valueRows = 0;

  constructor(
    public width = 300,
    public height = 150,
  ) {}

  resize(width: number, height: number): void {
    this.width = Math.max(1, width);
    this.height = Math.max(1, height);
  }

  toScreen(p: readonly number[]): [number, number] {
    return [
      this.width / 2 + (p[0] - this.centerX) * this.scaleX,
      this.height / 2 - (p[1] - this.centerY) * this.scaleY,
    ];
  }

  depth(): number {
    return 0;
  }

  toWorld(p: readonly number[]): number[] {
    return [
      this.centerX + (p[0] - this.width / 2) / this.scaleX,
      this.centerY - (p[1] - this.height / 2) / this.scaleY,
    ];
  }

  /** World length of `pixels` screen pixels, horizontally. */
  worldLength(pixels: number): number {
    return pixels / this.scaleX;
  }

  /**
   * Shows `bounds` with `padding` pixels around it. With `uniform` (the default
   * for geometry) one unit is as long across as up; plots may stretch. A
   * number lets a unit be up to that many times as long across as up, never
   * longer up than across (a table fills a short, wide box; a tall one keeps
   * its squares).
   */
  fit(
    bounds: Bounds,
    padding: number | readonly [number, number] = 40,
    uniform: boolean | number = true,
  ): void {
    const [padX, padY] = typeof padding === 'number' ? [padding, padding] : padding;
    const spanX = Math.max(bounds.maxX - bounds.minX, 1e-9);
    const spanY = Math.max(bounds.maxY - bounds.minY, 1e-9);
    const innerW = Math.max(this.width - 2 * padX, 10);
    const innerH = Math.max(this.height - 2 * padY, 10);
    let sx = innerW / spanX;
    let sy = innerH / spanY;
    if (typeof uniform === 'number' && sx > 0 && sy > 0) {
      sy = Math.min(sx, sy);
      sx = Math.min(sx, uniform * sy);
    } else if (uniform) {
      // A degenerate box (all points on a line or one spot) still gets a sane zoom.
      const s = Math.min(sx, sy);
      const fallback = Math.min(innerW, innerH) / 2;
      sx = sy = Number.isFinite(s) && s < 1e12 ? s : fallback;
      if (spanX <= 1e-9 && spanY <= 1e-9) sx = sy = fallback;
    }
    this.scaleX = sx;
    this.scaleY = sy;
    this.centerX = (bounds.minX + bounds.maxX) / 2;
    this.centerY = (bounds.minY + bounds.maxY) / 2;
  }

  dragBy(dx: number, dy: number): void {
    this.panBy(dx, dy);
  }

  panBy(dxPixels: number, dyPixels: number): void {
    this.centerX -= dxPixels / this.scaleX;
    this.centerY += dyPixels / this.scaleY;
  }

  /** Zooms by `factor` keeping the world point under `screen` fixed. */
  zoomAt(screen: readonly number[], factor: number): void {
    const before = this.toWorld(screen);
    const clamp = (s: number) => Math.min(Math.max(s * factor, MIN_SCALE), MAX_SCALE);
    this.scaleX = clamp(this.scaleX);
    this.scaleY = clamp(this.scaleY);
    const after = this.toWorld(screen);
    this.centerX += before[0] - after[0];
    this.centerY += before[1] - after[1];
  }

  /** The world rectangle currently visible. */
  visibleBounds(): Bounds {
    const a = this.toWorld([0, this.height]);
    const b = this.toWorld([this.width, 0]);
    return { minX: a[0], minY: a[1], maxX: b[0], maxY: b[1] };
  }

  /** `cx,cy,scale` (a geometry figure's scale is the same on both axes). */
  encode(): string {
    return [this.centerX, this.centerY, this.scaleX].map(viewNumber).join(',');
  }

  decode(text: string): boolean {
    const values = readNumbers(text, 3);
    if (!values) return false;
    const [cx, cy, s] = values;
    if (Math.abs(cx) > 1e9 || Math.abs(cy) > 1e9 || !(s >= MIN_SCALE && s <= MAX_SCALE))
      return false;
    this.centerX = cx;
    this.centerY = cy;
    this.scaleX = this.scaleY = s;
    return true;
  }
}
