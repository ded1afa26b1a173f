/**
 * Which arrangement of its figures presenter view gives a scene. A lesson
 * lays out a curve with its plot under it, which suits a wide subject; a
 * tall one (a curve with its control points high above it, Hermite's arrows)
 * is then fitted to the height of a short, wide box and leaves most of the
 * projector's width empty. A lesson may declare a `tallLayout` (the plot
 * beside the curve): presenter view takes it for a scene when it draws every
 * figure in the plane larger by a clear margin, with no plot squeezed.
 */
import { fitFigure, fitPadding } from './headless';
import type { FigureSpec, LayoutNode } from './lesson';
import { presenterSizes } from './figureSizes';
import type { Theme } from '../render/theme';
import { Viewport } from '../render/viewport';

/** How much larger the tall arrangement must draw the subject to be taken: a clear gain, not a coin toss. */
export const TALL_GAIN = 1.2;
/** No figure is made smaller than this by the tall arrangement (CSS px): a plot's numbers need room. */
const SMALLEST_SIDE = { width: 420, height: 240 };

type Layout = 'row' | 'column' | LayoutNode | undefined;

interface Arranged<S, M> {
  readonly layout?: Layout;
  readonly tallLayout?: LayoutNode;
  readonly figures: readonly FigureSpec<S, M>[];
}

/**
 * The layout for these shown figures of `model` in a figure area of `area`
 * CSS px: the lesson's `tallLayout` when it draws the smallest figure in the
 * plane at least TALL_GAIN times larger, no figure under SMALLEST_SIDE that
 * was not already, and every view in space nearly as large (SPACE_KEPT);
 * else the lesson's own layout.
 */
export function layoutFor<S, M>(
  lesson: Arranged<S, M>,
  shown: readonly FigureSpec<S, M>[],
  model: M,
  area: { width: number; height: number },
  theme: Theme,
): Layout {
  const tall = lesson.tallLayout;
  if (!tall || area.width <= 0 || area.height <= 0) return lesson.layout;
  const plain = arrangement(lesson.layout, shown, model, area, theme);
  const turned = arrangement(tall, shown, model, area, theme);
  if (!(turned.scale >= TALL_GAIN * plain.scale)) return lesson.layout;
  if (turned.squeezed > plain.squeezed) return lesson.layout;
  // A view in space fits a sphere round its subject: its smaller side is its scale.
  return turned.space >= SPACE_KEPT * plain.space ? tall : lesson.layout;
}

/** A view in space may lose at most this share of its size to the curve's gain. */
const SPACE_KEPT = 0.9;

/**
 * The smallest scale (px per unit) of the figures in the plane, the smallest
 * side of the views in space, and how many figures are under the smallest size.
 */
function arrangement<S, M>(
  layout: Layout,
  shown: readonly FigureSpec<S, M>[],
  model: M,
  area: { width: number; height: number },
  theme: Theme,
): { scale: number; space: number; squeezed: number } {
  const sizes = presenterSizes(layout, shown, area, theme.sizes.strip ?? 1);
  let scale = Infinity;
  let space = Infinity;
  let squeezed = 0;
  for (const figure of shown) {
    const size = sizes.get(figure.id);
    if (!size) continue;
    if (size.width < SMALLEST_SIDE.width || size.height < SMALLEST_SIDE.height) squeezed++;
    if (figure.kind === 'space') space = Math.min(space, size.width, size.height);
    if (figure.kind !== 'geometry') continue;
    scale = Math.min(scale, fittedScale(figure, model, size.width, size.height, theme));
  }
  return { scale, space, squeezed };
}

/** Pixels per unit of a figure in the plane fitted to its subject in a box of this size, as the page fits it. */
export function fittedScale<S, M>(
  figure: FigureSpec<S, M>,
  model: M,
  width: number,
  height: number,
  theme: Theme,
): number {
  const view = new Viewport(width, height);
  fitFigure(view, figure, model, theme, fitPadding(figure, theme, width, height));
  return Math.min(view.scaleX, view.scaleY);
}
