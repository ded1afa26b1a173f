/**
 * Drawing in space on a Canvas 2D: lines, shaded quads, points and labels are
 * collected with their depth and drawn far to near (the painter's algorithm),
 * so a surface hides what is behind it without WebGL. Quads are flat-shaded
 * from a fixed light.
 */
import type { LabelStyle } from './labels';
import type { Painter, StrokeStyle } from './painter';
import type { OrbitCamera } from './orbitCamera';

type P = readonly number[];

type Item =
  | { kind: 'line'; depth: number; a: P; b: P; style: StrokeStyle }
  | { kind: 'quad'; depth: number; points: P[]; fill: string; alpha: number; edge?: StrokeStyle }
  | { kind: 'dot'; depth: number; p: P; color: string; radius: number }
  | { kind: 'label'; depth: number; text: string; p: P; style: LabelStyle };

/** Light from above, over the viewer's right shoulder (camera coordinates). */
const LIGHT = normalize([0.35, 0.45, 0.82]);

function normalize(v: readonly number[]): number[] {
  const length = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / length, v[1] / length, v[2] / length];
}

const sub = (a: P, b: P) => [a[0] - b[0], a[1] - b[1], (a[2] ?? 0) - (b[2] ?? 0)];
const cross = (a: P, b: P) => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];

/** `#rrggbb` scaled towards black by `k` (0…1). */
export function shade(color: string, k: number): string {
  const m = /^#([0-9a-f]{6})$/i.exec(color);
  if (!m) return color;
  const n = parseInt(m[1], 16);
  const channel = (shift: number) =>
    Math.round(((n >> shift) & 255) * Math.max(0, Math.min(1, k)))
      .toString(16)
      .padStart(2, '0');
  return `#${channel(16)}${channel(8)}${channel(0)}`;
}

export class SpaceScene {
  private readonly items: Item[] = [];

  constructor(
    private readonly painter: Painter,
    private readonly camera: OrbitCamera,
  ) {}

  private depth(points: readonly P[]): number {
    let sum = 0;
    for (const p of points) sum += this.camera.depth(p);
    return sum / points.length;
  }

  line(a: P, b: P, style: StrokeStyle = {}): void {
    this.items.push({ kind: 'line', depth: this.depth([a, b]), a, b, style });
  }

  /** A polyline, cut into segments so each is sorted by its own depth. */
  polyline(points: readonly P[], style: StrokeStyle = {}): void {
    for (let i = 1; i < points.length; i++) this.line(points[i - 1], points[i], style);
  }

  /**
   * A flat-shaded quadrilateral (or triangle): its brightness follows the angle
   * between its normal and the light, whichever side faces the viewer.
   */
  quad(points: P[], color: string, options: { alpha?: number; edge?: StrokeStyle } = {}): void {
    const n = normalize(
      cross(sub(points[2], points[0]), sub(points[points.length - 1], points[1])),
    );
    const back = this.camera.towardsViewer();
    // The light is fixed to the viewer: express it in world coordinates.
    const facing = n[0] * back[0] + n[1] * back[1] + n[2] * back[2];
    const sign = facing < 0 ? -1 : 1;
    const light = this.lightInWorld();
    const lambert = Math.abs(sign * (n[0] * light[0] + n[1] * light[1] + n[2] * light[2]));
    const fill = shade(color, 0.35 + 0.65 * lambert);
    this.items.push({
      kind: 'quad',
      depth: this.depth(points),
      points,
      fill,
      alpha: options.alpha ?? 1,
      edge: options.edge,
    });
  }

  private lightInWorld(): number[] {
    const { right, up, back } = this.camera;
    return normalize(
      [0, 1, 2].map((i) => LIGHT[0] * right[i] + LIGHT[1] * up[i] + LIGHT[2] * back[i]),
    );
  }

  dot(p: P, color: string, radius = this.painter.sizes.point): void {
    this.items.push({ kind: 'dot', depth: this.camera.depth(p), p, color, radius });
  }

  label(text: string, p: P, style: LabelStyle = {}): void {
    // A label sits just in front of its point.
    this.items.push({ kind: 'label', depth: this.camera.depth(p) - 1e-9, text, p, style });
  }

  /** Draws everything collected, far to near, and forgets it. */
  flush(): void {
    const painter = this.painter;
    const items = this.items;
    items.sort((a, b) => b.depth - a.depth);
    for (let i = 0; i < items.length; i++) {
      const item = items[i];
      switch (item.kind) {
        case 'line': {
          // A run of lines in one style (neighbours in depth) is one stroke.
          const run: [P, P][] = [[item.a, item.b]];
          for (let next = items[i + 1]; next?.kind === 'line' && next.style === item.style;) {
            run.push([next.a, next.b]);
            next = items[++i + 1];
          }
          painter.segments(run, item.style);
          break;
        }
        case 'quad': {
          if (item.edge) {
            painter.polygon(item.points, item.fill, item.alpha, item.edge);
            break;
          }
          // A run of unoutlined quads is filled in one go.
          const run = [item];
          for (let next = items[i + 1]; next?.kind === 'quad' && !next.edge;) {
            run.push(next);
            next = items[++i + 1];
          }
          painter.facets(run);
          break;
        }
        case 'dot':
          painter.dot(item.p, item.color, item.radius);
          break;
        case 'label':
          painter.label(item.text, item.p, item.style);
          break;
      }
    }
    this.items.length = 0;
  }
}
