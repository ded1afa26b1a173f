/**
 * A figure's movable points as drawn: the handle and its lecture label. The
 * screen, the SVG export and the tests draw them with this one routine.
 */
import type { Handle } from '../app/lesson';
import { type HandleState, Painter, splitSubscripts } from './painter';

/** Plain-text name of a lecture label: `P_{1,2}` → `P1,2`. */
export const plainLabel = (label: string) =>
  splitSubscripts(label)
    .map((r) => r.text)
    .join('');

/** Draws a figure's handles with their labels (the screen, exports and tests use this one routine). */
export function drawHandles(
  painter: Painter,
  handles: readonly Handle[],
  stateOf: (handle: Handle) => HandleState = () => 'idle',
): void {
  const theme = painter.theme;
  for (const handle of handles) {
    const state = stateOf(handle);
    painter.handle(handle.position, {
      color: handle.color,
      shape: handle.shape,
      state,
      // A small handle grows to full size while it is held, hovered or focused.
      radius: handle.small && state === 'idle' ? theme.sizes.handle * 0.5 : undefined,
    });
    if (handle.showLabel !== false && painter.show.labels) {
      painter.label(handle.label, handle.position, {
        dx: theme.sizes.handle + 4,
        dy: -(theme.sizes.handle + theme.sizes.label * 0.45),
        color: handle.color ?? theme.ink,
        halo: true,
        bold: true,
      });
    }
  }
}
