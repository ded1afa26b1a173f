/**
 * A live table's cells through a drag: a lone number in a box of its own
 * (it cannot wrap), and words held in a box of their size from the press to
 * the release (they must wrap as a column narrows between drags). Either way
 * a drag that changes them lays out their boxes, not the table and the page
 * round them.
 */
import { BOX, fix, measure } from './boxFix';
import { dropBox, freeBox } from './liveBoxes';
import { onDragStart, whenReleased } from './unseen';

/** One number, with no space in it: text that cannot wrap, so a box of its own size never cuts it. */
export const boxesNumber = (text: string): boolean => /^[−+-]?[\d.,]+$/.test(text);

/**
 * A table cell's text is about to be `text`: a lone number gets a box of its
 * own (a drag that changes it lays out the box, not the table and the page
 * round it), and words do not, so that a cell can still wrap when its column
 * narrows (on a phone, “Σ fₘ fₙ Pₘ,ₙ” fixed on one line ran surface's table
 * 343 px in 336). Only a whole cell: a box inside words would read with a
 * space either side of it, as Chromium names a row from its cells (“P( 0.3 )”).
 */
export function boxIfNumber(el: HTMLElement, text: string): void {
  if (el.dataset[BOX] === 'held') return;
  const number = boxesNumber(text);
  if (number && !el.dataset[BOX]) freeBox(el);
  else if (!number && el.dataset[BOX]) dropBox(el);
}

/** The words of a live table cell (a point, a weight worked out): held in a box while a pointer is. */
export const HELD_CELL = 'cell';

/**
 * A drag began: each live table cell of words on screen is held in a box of
 * the size it has now, till the pointer is let go. A drag that changes
 * a point's coordinates then lays out those boxes, not the table and the page
 * round them; between drags the cells are free, to wrap as their column
 * narrows (a phone), and they are not named with a space either side of a
 * box (“P( 0.3 )”), as a box inside words would be. One read, then one pass
 * of writes.
 */
export function holdCells(root: ParentNode): void {
  if (typeof innerHeight !== 'number') return;
  const cells = [...root.querySelectorAll<HTMLElement>(`[data-${HELD_CELL}]:not([data-${BOX}])`)];
  // Every cell of a table in view: a table is written whole once any of it shows (unseen.ts).
  const onScreen = cells.filter((el) => {
    const box = (el.closest('table') ?? el).getBoundingClientRect();
    return box.width > 0 && box.bottom > 0 && box.top < innerHeight;
  });
  const measured = measure(onScreen);
  const held = onScreen.filter((el, i) => fix(el, measured[i], 'held') !== null);
  if (held.length > 0)
    whenReleased(() => {
      for (const el of held) if (el.dataset[BOX] === 'held') dropBox(el);
    });
}

/**
 * Only a drag of a figure's point or of a slider holds the cells, on its
 * first move: neither changes a table's columns. Held at every press, a click
 * on "Add a control point" kept de Casteljau's split cells at their old width
 * as the table gained a column, and they grew over the button and took the
 * next click (de-casteljau.spec, 3 of 3 runs).
 */
const HOLDS = '.figure, input[type=range]';

onDragStart((pressed) => {
  if (pressed instanceof Element && pressed.closest(HOLDS)) holdCells(document);
});
