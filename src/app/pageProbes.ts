/**
 * What tests and tools driving a lesson page ask of its figures (through
 * `window.splineLab`): where a point is on the screen, and where each
 * figure's labels were placed in its last frame.
 */
import type { LabelBox } from '../render/labels';
import type { FigureView } from './figureView';
import type { Point } from './lesson';

/**
 * Where a figure's point is on the screen (client pixels), and where its
 * handle `id` is in the figure's coordinates: for tests that drag a point
 * to a place worked out by hand.
 */
export function probeFigure<S, M>(
  figures: readonly FigureView<S, M>[],
  figure: string,
  point: readonly number[] | null,
  id: string | null,
) {
  const view = figures.find((f) => f.spec.id === figure);
  if (!view) return null;
  // Only a point asks for the page's layout: a handle alone is read without
  // one (the bench reads it after every drag frame).
  const screen = point ? view.view.toScreen(point as Point) : null;
  const box = screen ? view.canvas.getBoundingClientRect() : null;
  const handle = id ? view.handlePosition(id) : null;
  return {
    screen: screen && box ? [box.left + screen[0], box.top + screen[1]] : null,
    handle,
  };
}

/** Each figure's labels as last drawn, with its size: for the overlap check. */
export function labelBoxesOf<S, M>(
  figures: readonly FigureView<S, M>[],
): {
  figure: string;
  width: number;
  height: number;
  labels: readonly LabelBox[];
  crossed: string[];
}[] {
  return figures.map((f) => ({
    figure: f.spec.id,
    width: f.view.width,
    height: f.view.height,
    labels: f.labels,
    crossed: f.crossedLabels(),
  }));
}
