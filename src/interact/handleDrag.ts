/**
 * What dragging a movable point means, apart from any canvas (mafs: drag
 * logic apart from the view): which point a press picks, how handles stacked
 * on one spot are told apart by the drag's direction, where the point goes on
 * the drag plane (the plane facing the viewer in space) or along one axis,
 * and how far a key press moves it.
 */
import type { Point } from '../math';
import { OrbitCamera } from '../render/orbitCamera';
import { type Projection, niceStep } from '../render/projection';

export type Screen = readonly [number, number];

/** What the drag logic needs of a handle. */
export interface Movable {
  id: string;
  position: Point;
  /** The world direction in which pulling picks this one from a stack. */
  pull?: Point;
}

/** How far (pixels) a stacked grab moves before its direction picks the handle. */
const PULL_SLOP = 4;
const AXES: Point[] = [
  [1, 0, 0],
  [0, 1, 0],
  [0, 0, 1],
];

const hypot = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);

/** The handle nearest `at` within `reach` pixels; later handles win ties (they are drawn on top). */
export function nearestHandle(
  handles: readonly Movable[],
  view: Projection,
  at: Screen,
  reach: number,
): string | null {
  let best: string | null = null;
  let bestDistance = reach;
  for (const handle of handles) {
    const d = hypot(view.toScreen(handle.position), at);
    if (d <= bestDistance) {
      best = handle.id;
      bestDistance = d;
    }
  }
  return best;
}

/** One drag of one handle (or of a stack, until the direction picks one). */
export class HandleDrag {
  id: string;
  private stack: string[] | null;
  private readonly start: Screen;
  /** Screen offset from the pointer to the handle's centre. */
  private readonly offset: [number, number];
  /** Where the handle was when grabbed: the drag plane passes through it. */
  private readonly anchor: Point;
  /** Along one world axis (space, Shift held), chosen by the first motion. */
  private axis: Point | null = null;

  constructor(
    private readonly view: Projection,
    private readonly handles: readonly Movable[],
    id: string,
    at: Screen,
  ) {
    this.id = id;
    this.start = at;
    const handle = handles.find((h) => h.id === id);
    if (!handle) {
      // Grabbed away from any handle (a cursor line, say): nothing to stack with.
      this.stack = null;
      this.offset = [0, 0];
      this.anchor = view.toWorld(at);
      return;
    }
    const screen = view.toScreen(handle.position);
    const stack = handles.filter((h) => hypot(view.toScreen(h.position), screen) < 1);
    this.stack = stack.length > 1 ? stack.map((h) => h.id) : null;
    this.offset = [screen[0] - at[0], screen[1] - at[1]];
    this.anchor = handle.position;
  }

  /** Where the pointer at `at` puts the handle, or null while a stack is still undecided. */
  move(at: Screen, shift: boolean): { id: string; to: Point } | null {
    const motion: [number, number] = [at[0] - this.start[0], at[1] - this.start[1]];
    const moved = Math.hypot(motion[0], motion[1]) >= PULL_SLOP;
    if (this.stack) {
      if (!moved) return null;
      this.id = this.choose(this.stack, motion);
      this.stack = null;
    }
    const screen: Screen = [at[0] + this.offset[0], at[1] + this.offset[1]];
    const view = this.view;
    if (!(view instanceof OrbitCamera)) return { id: this.id, to: view.toWorld(screen) };
    if (!shift) this.axis = null;
    else if (!this.axis && moved) {
      // Along the world axis whose screen direction is closest to the motion.
      const scores = AXES.map((axis) => {
        const [dx, dy] = view.screenDirection(this.anchor, axis);
        return Math.abs(dx * motion[0] + dy * motion[1]);
      });
      this.axis = AXES[scores.indexOf(Math.max(...scores))];
    }
    const to = this.axis
      ? view.closestOnAxis(screen, this.anchor, [...this.axis])
      : view.toWorld(screen, this.anchor);
    return { id: this.id, to };
  }

  /** Of handles stacked on one spot, the one this pull (screen motion) means. */
  private choose(stack: string[], motion: [number, number]): string {
    const byId = new Map(this.handles.map((h) => [h.id, h]));
    if (stack.some((id) => byId.get(id)?.pull)) {
      let best = stack[0];
      let bestScore = -Infinity;
      for (const id of stack) {
        const { position, pull } = byId.get(id)!;
        if (!pull) continue;
        const a = this.view.toScreen(position);
        const reach = this.view.worldLength(40, position);
        const b = this.view.toScreen(position.map((v, k) => v + (pull[k] ?? 0) * reach));
        const score = ((b[0] - a[0]) * motion[0] + (b[1] - a[1]) * motion[1]) / (hypot(a, b) || 1);
        if (score > bestScore) {
          bestScore = score;
          best = id;
        }
      }
      return best;
    }
    // Right or up (screen y down) picks the last of the stack, left or down the first.
    return motion[0] - motion[1] >= 0 ? stack[stack.length - 1] : stack[0];
  }
}

export type KeySize = 'normal' | 'big' | 'fine';

/**
 * Where a key press moves a point: about 8 pixels a press along each world
 * axis named in `delta`, on that axis's own scale (a plot's axes differ),
 * landing on a nice step; the other coordinates stay exact.
 */
export function keyStep(
  view: Projection,
  p: Point,
  delta: readonly number[],
  size: KeySize,
): Point {
  const factor = size === 'big' ? 10 : size === 'fine' ? 0.1 : 1;
  const origin = view.toScreen(p);
  const stepFor = (axis: number) => {
    if (view.dimension === 3) return niceStep(view.worldLength(8, p)) * factor;
    const unit = p.map((v, k) => (k === axis ? v + 1 : v));
    return niceStep(8 / hypot(view.toScreen(unit), origin)) * factor;
  };
  const snap = (v: number, step: number) => Number((Math.round(v / step) * step).toPrecision(12));
  return p.map((v, k) => (delta[k] ? snap(v + delta[k] * stepFor(k), stepFor(k)) : v));
}
