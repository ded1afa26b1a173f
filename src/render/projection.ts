/**
 * What drawing code asks of a figure's view, in 2D or in space: where a world
 * point lands on screen (CSS pixels, y down), how far it is from the viewer,
 * and which world point lies under a screen point. The 2D `Viewport` and the
 * 3D `OrbitCamera` both implement it, so a painter or a drag does not care
 * which it has.
 */
export type WorldPoint = readonly number[];
export type ScreenPoint = readonly [number, number];

/** An axis-aligned box in world coordinates (z present in space). */
export interface Bounds {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
  minZ?: number;
  maxZ?: number;
}

export interface Projection {
  readonly width: number;
  readonly height: number;
  /** 2 for the plane, 3 for space. */
  readonly dimension: 2 | 3;
  /** Straight lines and Bézier curves stay what they are on screen (no perspective). */
  readonly affine: boolean;
  toScreen(p: WorldPoint): [number, number];
  /** Distance from the viewer along the view direction (larger is farther); 0 in 2D. */
  depth(p: WorldPoint): number;
  /**
   * The world point under `screen`: in 2D the inverse map; in space the point
   * on the plane through `anchor` that faces the viewer (the drag plane).
   */
  toWorld(screen: readonly number[], anchor?: WorldPoint): number[];
  /** World length of `pixels` screen pixels near `at` (horizontally in 2D). */
  worldLength(pixels: number, at?: WorldPoint): number;
  resize(width: number, height: number): void;
  /** Shows `bounds` with `padding` pixels around it (or [left and right, top and bottom]). */
  fit(
    bounds: Bounds,
    padding: number | readonly [number, number],
    uniform?: boolean | number,
  ): void;
  /** Drag of empty space: pan in 2D, orbit in space. */
  dragBy(dx: number, dy: number): void;
  zoomAt(screen: readonly number[], factor: number): void;
  /** The view as a short string for the link, and back (false if unreadable). */
  encode(): string;
  decode(text: string): boolean;
}

/** The length of a box's diagonal in the plane: a figure's size, to scale marks by. */
export const diagonal = (b: Bounds): number => Math.hypot(b.maxX - b.minX, b.maxY - b.minY);

/** Smallest box holding every point (z too, where points have it); a unit box if none. */
export function boundsOf(points: readonly WorldPoint[]): Bounds {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  let minZ = Infinity;
  let maxZ = -Infinity;
  for (const p of points) {
    if (p[0] < minX) minX = p[0];
    if (p[0] > maxX) maxX = p[0];
    if (p[1] < minY) minY = p[1];
    if (p[1] > maxY) maxY = p[1];
    if (p.length > 2) {
      if (p[2] < minZ) minZ = p[2];
      if (p[2] > maxZ) maxZ = p[2];
    }
  }
  if (!Number.isFinite(minX)) return { minX: -1, minY: -1, maxX: 1, maxY: 1 };
  return Number.isFinite(minZ)
    ? { minX, minY, maxX, maxY, minZ, maxZ }
    : { minX, minY, maxX, maxY };
}

export function unionBounds(a: Bounds, b: Bounds): Bounds {
  const box: Bounds = {
    minX: Math.min(a.minX, b.minX),
    minY: Math.min(a.minY, b.minY),
    maxX: Math.max(a.maxX, b.maxX),
    maxY: Math.max(a.maxY, b.maxY),
  };
  if (a.minZ !== undefined || b.minZ !== undefined) {
    box.minZ = Math.min(a.minZ ?? Infinity, b.minZ ?? Infinity);
    box.maxZ = Math.max(a.maxZ ?? -Infinity, b.maxZ ?? -Infinity);
  }
  return box;
}

/** A "nice" step (1, 2 or 5 × 10^k) close to `rough`: for grids and keyboard moves. */
export function niceStep(rough: number): number {
  if (!(rough > 0) || !Number.isFinite(rough)) return 1;
  const power = Math.pow(10, Math.floor(Math.log10(rough)));
  const m = rough / power;
  const nice = m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10;
  return nice * power;
}

/** Numbers for a view in a link: ten significant digits, no exponent noise. */
export const viewNumber = (v: number) => String(Number(v.toPrecision(10)));

/** Reads `count` finite numbers separated by commas, or null. */
export function readNumbers(text: string, count: number): number[] | null {
  const parts = text.split(',');
  if (parts.length !== count) return null;
  const values: number[] = [];
  for (const part of parts) {
    if (!/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(part)) return null;
    const v = Number(part);
    if (!Number.isFinite(v)) return null;
    values.push(v);
  }
  return values;
}
