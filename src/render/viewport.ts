/**
 * The one mapping between lesson coordinates (y up) and CSS pixels (y down).
 * Device pixels are the canvas's business (see canvasFigure.ts); everything a
 * lesson draws goes through here.
 */
export type Point2 = readonly [number, number];

export interface Bounds {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

export function boundsOf(points: readonly (readonly number[])[]): Bounds {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (const p of points) {
    if (p[0] < minX) minX = p[0];
    if (p[0] > maxX) maxX = p[0];
    if (p[1] < minY) minY = p[1];
    if (p[1] > maxY) maxY = p[1];
  }
  if (!Number.isFinite(minX)) return { minX: -1, minY: -1, maxX: 1, maxY: 1 };
  return { minX, minY, maxX, maxY };
}

export function unionBounds(a: Bounds, b: Bounds): Bounds {
  return {
    minX: Math.min(a.minX, b.minX),
    minY: Math.min(a.minY, b.minY),
    maxX: Math.max(a.maxX, b.maxX),
    maxY: Math.max(a.maxY, b.maxY),
  };
}

export class Viewport {
  /** World coordinates at the centre of the view. */
  centerX = 0;
  centerY = 0;
  /** Pixels per world unit, horizontally and vertically. */
  scaleX = 100;
  scaleY = 100;

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

  toWorld(p: readonly number[]): [number, number] {
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
   * for geometry) one unit is as long across as up; plots may stretch.
   */
  fit(bounds: Bounds, padding = 40, uniform = true): void {
    const spanX = Math.max(bounds.maxX - bounds.minX, 1e-9);
    const spanY = Math.max(bounds.maxY - bounds.minY, 1e-9);
    const innerW = Math.max(this.width - 2 * padding, 10);
    const innerH = Math.max(this.height - 2 * padding, 10);
    let sx = innerW / spanX;
    let sy = innerH / spanY;
    if (uniform) {
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

  panBy(dxPixels: number, dyPixels: number): void {
    this.centerX -= dxPixels / this.scaleX;
    this.centerY += dyPixels / this.scaleY;
  }

  /** Zooms by `factor` keeping the world point under `screen` fixed. */
  zoomAt(screen: readonly number[], factor: number): void {
    const before = this.toWorld(screen);
    const clamp = (s: number) => Math.min(Math.max(s * factor, 1e-6), 1e9);
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
}

/** A "nice" step (1, 2 or 5 × 10^k) close to `rough`: for grids and keyboard moves. */
export function niceStep(rough: number): number {
  if (!(rough > 0) || !Number.isFinite(rough)) return 1;
  const power = Math.pow(10, Math.floor(Math.log10(rough)));
  const m = rough / power;
  const nice = m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10;
  return nice * power;
}
