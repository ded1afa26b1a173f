/**
 * The figure's rectangle in screen pixels: the clip a painter draws into
 * (the view and a margin), and whether a point lies on the figure.
 */
import type { ClipRect } from './clip';
import type { Projection } from './projection';

/** How far outside the figure drawing still reaches (pixels): thick strokes and arrow heads. */
const MARGIN = 64;

/** The screen rectangle a figure's drawing is cut to: the view and a margin. */
export function figureClip(view: Projection): ClipRect {
  return {
    minX: -MARGIN,
    minY: -MARGIN,
    maxX: view.width + MARGIN,
    maxY: view.height + MARGIN,
  };
}

/** Is a screen point on the figure (within `margin` pixels of it)? */
export function onFigure(view: Projection, x: number, y: number, margin = 0): boolean {
  return x >= -margin && y >= -margin && x <= view.width + margin && y <= view.height + margin;
}
