/**
 * The labels a figure asks the painter for: at a world point, beside one
 * clear of others, or at screen pixels; each drawn at once or, while labels
 * are held (labelOrder), placed once the figure is down, its width known
 * before.
 */
import { onFigure } from './figureRect';
import type { LabelStyle } from './labels';
import { drawLabelClear } from './labelClear';
import type { LabelOrder } from './labelOrder';
import { drawScreenLabel } from './screenLabel';
import { labelWidth } from './labelWidth';
import type { P, Painter } from './painter';

/**
 * A label naming the world point `p`, offset by the style's dx, dy. A point
 * off screen gets no label (it would pile up at the edge).
 */
export function labelPoint(painter: Painter, text: string, p: P, style: LabelStyle): void {
  const [x, y] = painter.view.toScreen(p);
  if (!onFigure(painter.view, x, y)) return;
  painter.screenLabel(text, x + (style.dx ?? 0), y + (style.dy ?? 0), {
    ...style,
    names: true,
    of: [x, y],
  });
}

/** A label beside the world point `p` on whichever side lies farthest from the `avoid` points. */
export function labelPointClear(
  painter: Painter,
  text: string,
  p: P,
  avoid: readonly P[],
  style: LabelStyle,
): void {
  const [x, y] = painter.view.toScreen(p);
  if (!onFigure(painter.view, x, y) || painter.labelHidden(text)) return;
  painter.placing(() => drawLabelClear(painter, text, [x, y], avoid, style));
}

/** A label at screen coordinates (pixels), now or when `order`'s held labels are placed; its width. */
export function labelScreen(
  painter: Painter,
  order: LabelOrder,
  text: string,
  x: number,
  y: number,
  style: LabelStyle,
): { width: number } {
  if (painter.labelHidden(text)) return { width: 0 };
  if (!order.holding) return drawScreenLabel(painter, text, x, y, style);
  order.placing(() => drawScreenLabel(painter, text, x, y, style));
  return { width: labelWidth(painter, text, style) };
}
