/**
 * What a figure's picture was drawn from (`FigureSpec.drawnFrom`), so that a
 * frame that would draw the very picture on its canvas now is skipped: a plot
 * of basis functions is not drawn again while a point it does not depend on
 * is dragged.
 */
import { sameValues } from '../kit/memoOn';
import type { Theme } from '../render/theme';
import type { FigureHost } from './figureView';
import type { FigureSpec } from './lesson';

/** What the memo needs of the page: what else the picture shows. */
export type DrawnFromHost<S, M> = Pick<
  FigureHost<S, M>,
  'ghost' | 'trail' | 'marks' | 'shown' | 'info'
>;

/** The values the canvas's picture was last drawn from, or null (draw it). */
export class DrawnFrom<S, M> {
  private last: readonly unknown[] | null = null;

  constructor(
    private readonly spec: FigureSpec<S, M>,
    private readonly host: DrawnFromHost<S, M>,
  ) {}

  /**
   * True if the picture for `model` is the one on the canvas now, unless it
   * must be drawn `anyway`; else what it is drawn from now is kept.
   */
  unchanged(model: M, theme: Theme, anyway: boolean): boolean {
    const from = this.now(model, theme);
    if (!anyway && from && this.last && sameValues(from, this.last)) return true;
    this.last = from;
    return false;
  }

  /** The picture must be drawn in the next frame, whatever it is drawn from. */
  forget(): void {
    this.last = null;
  }

  /**
   * What the picture is drawn from now, when the figure says (else null: it is
   * drawn every frame): its own values, and the theme, the pointer's hover
   * and the step. A ghost, a trail or practice marks are drawn every time.
   */
  private now(model: M, theme: Theme): readonly unknown[] | null {
    const own = this.spec.drawnFrom?.(model);
    if (!own) return null;
    const id = this.spec.id;
    if (this.host.ghost() !== null || this.host.trail(id) || this.host.marks(id).length)
      return null;
    const { curve, labels, numbers } = this.host.shown();
    return [theme, this.host.info().hover, curve, labels, numbers, ...own];
  }
}
