import type { FigureSpec, Point } from './lesson';

/** Points of a trail kept per figure (a long play is thinned to this many). */
const TRAIL_MAX = 4000;

/**
 * The presenter's trail tool: each figure's moving point (its `trail`, e.g.
 * P(t)) kept state after state while the parameter plays, for the figure to
 * draw as the path it traced.
 */
export class Trails {
  private readonly byFigure = new Map<string, Point[]>();

  /** The moving points of this model, added to their figures' trails. */
  extend<M>(
    figures: readonly { spec: Pick<FigureSpec<unknown, M>, 'id' | 'trail'> }[],
    model: M,
  ): void {
    for (const { spec } of figures) {
      const point = spec.trail?.(model);
      if (!point) continue;
      const trail = this.byFigure.get(spec.id) ?? [];
      const last = trail[trail.length - 1];
      if (!last || last.some((v, i) => v !== point[i])) trail.push(point);
      if (trail.length > TRAIL_MAX) trail.splice(0, trail.length - TRAIL_MAX / 2);
      this.byFigure.set(spec.id, trail);
    }
  }

  /** The trail of a figure, or null if it has none. */
  of(figure: string): Point[] | null {
    return this.byFigure.get(figure) ?? null;
  }

  clear(): void {
    this.byFigure.clear();
  }
}
