/**
 * A figure's movable points as drawn: the handle and its lecture label. The
 * screen, the SVG export and the tests draw them with this one routine.
 */
import type { Handle } from '../app/lesson';
import type { HandleState } from './handleDrawing';
import { splitSubscripts } from './labels';
import { Painter } from './painter';

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
  // A dot's outline is thin and it fits inside a curve's stroke: in presenter
  // view 3.5 px in a 7 px curve (the road's surface is 17 px wide).
  const dot = Math.max(2.5, theme.sizes.curve / 2);
  const radius = (handle: Handle, state: HandleState) =>
    // A small handle or a dot grows to full size while it is held, hovered or focused.
    state !== 'idle'
      ? theme.sizes.handle
      : handle.dot
        ? dot
        : handle.small
          ? theme.sizes.handle * 0.5
          : theme.sizes.handle;
  const ring = Math.max(1, theme.sizes.thin / 2);
  for (const handle of handles) {
    const state = stateOf(handle);
    painter.handle(handle.position, {
      color: handle.color,
      shape: handle.shape,
      state,
      radius: radius(handle, state),
      ring: handle.dot && state === 'idle' ? ring : undefined,
    });
  }
  // The point a step is about goes over them (P(0) is on P₀'s handle).
  painter.drawAbove();
  // The names after every handle is down: each goes to the first side of its
  // point where no line, point or other name runs through it.
  if (!painter.show.labels) return;
  // Each name goes nearer its own point than any other (P₃'s never beside P₄),
  // and the placer keeps it nearer than the figure's named points too (P₂'s
  // name beside P(u) reads as P(u)'s, P₃'s beside B₂ as B₂'s).
  const rivals = handles.map((handle) => painter.view.toScreen(handle.position));
  for (const handle of handles) {
    if (handle.showLabel === false) continue;
    painter.label(handle.label, handle.position, {
      around: radius(handle, stateOf(handle)) + theme.sizes.line,
      color: handle.color ?? theme.ink,
      halo: true,
      bold: true,
      rivals,
    });
  }
}
