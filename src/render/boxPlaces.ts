/**
 * Where a box may sit over a figure (a note, a key, a plot's name): the
 * places along its edges, and which of them is clear of every stroke, point
 * and label, or failing that hides least.
 */
import { type Box, boxesMeet } from './ink';
import type { Painter } from './painter';

/** How many labels placed so far lie under the box. */
const labelsUnder = (painter: Painter, box: Box) =>
  painter.labels.filter((b) => boxesMeet(b, box)).length;

/**
 * Of the places a box may go over the figure (a note, a key, a plot's name),
 * the first under which no stroke, point or label lies; -1 if none is clear.
 * A drawn box may cover the grid's axes; letters without one (`covers`
 * false: a heading) may not.
 */
export function firstClear(painter: Painter, boxes: readonly Box[], covers = true): number {
  return boxes.findIndex(
    (box) => labelsUnder(painter, box) === 0 && !painter.ink.crosses(box, covers),
  );
}

/**
 * The place that hides least (-1 if none): a handle hidden is worse than
 * anything else (it can no longer be grabbed), a point or a label worse than
 * any number of strokes crossed (the curve shows round it).
 */
export function leastHidden(painter: Painter, boxes: readonly Box[]): number {
  const hidden = boxes.map((box) => {
    const { discs, strokes } = painter.ink.hits(box);
    return (
      painter.ink.handlesUnder(box) * 1e6 + (discs + labelsUnder(painter, box)) * 1000 + strokes
    );
  });
  return hidden.indexOf(Math.min(...hidden));
}

/**
 * Where a box `width` × `height` may sit over a figure `margin` from its
 * edges: the four corners (top left first), then the middles of the top and
 * foot, then of the sides, for when every corner holds a handle. `top` is
 * the least y at the top (below a box already there).
 */
export function edgePlaces(
  view: { width: number; height: number },
  width: number,
  height: number,
  margin: number,
  top = margin,
): Box[] {
  const [right, foot] = [view.width - width - margin, view.height - height - margin];
  const [centre, middle] = [(view.width - width) / 2, (top + foot) / 2];
  return [
    [margin, top],
    [right, top],
    [margin, foot],
    [right, foot],
    [centre, top],
    [centre, foot],
    [margin, middle],
    [right, middle],
  ].map(([x, y]) => ({ x, y, width, height }));
}

/** The first clear place, else the one that hides least. */
export const clearestPlace = (painter: Painter, boxes: readonly Box[]): number => {
  const clear = firstClear(painter, boxes);
  return clear >= 0 ? clear : leastHidden(painter, boxes);
};
