import { describe, expect, it } from 'vitest';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/** A 600 × 400 figure of the unit square, a stroke through the part of it `stroke` names. */
function noteBox(stroke: 'top left' | 'top' | 'none', top?: number) {
  const view = new Viewport(600, 400);
  view.resize(600, 400);
  view.fit({ minX: 0, minY: 0, maxX: 1, maxY: 1 }, 0);
  const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
  painter.holdLabels();
  // y = 1 is the top edge; a line a little below it, across the left third or the whole width.
  if (stroke !== 'none')
    painter.polyline(
      [
        [0, 0.97],
        [stroke === 'top' ? 1 : 0.35, 0.97],
      ],
      { width: 3 },
    );
  painter.note('Both velocities are zero here: the curvature is undefined', { top });
  painter.placeLabels();
  return painter.labels.find((b) => b.text.startsWith('Both'))!;
}

describe('a figure’s note', () => {
  it('sits at the top left when nothing is drawn there', () => {
    const box = noteBox('none');
    expect(box.x).toBeLessThan(20);
    expect(box.y).toBeLessThan(20);
  });
  it('takes the top right when a line runs through the top left', () => {
    const box = noteBox('top left');
    expect(box.x + box.width).toBeGreaterThan(580);
    expect(box.y).toBeLessThan(20);
  });
  it('goes to the foot when a line runs across the whole top', () => {
    const box = noteBox('top');
    expect(box.y + box.height).toBeGreaterThan(380);
  });
  it('stays where it is told when given its top (notes stacked one under another)', () => {
    const box = noteBox('top', 50);
    expect(box.y).toBe(50);
    expect(box.x).toBeLessThan(20);
  });
});
