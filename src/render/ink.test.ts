import { describe, expect, it } from 'vitest';
import { Ink, segmentMeetsBox } from './ink';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

const box = { x: 10, y: 10, width: 20, height: 10 };

describe('Ink: what a frame put on screen, asked box by box', () => {
  it('finds a stroke through a box, and none that passes by (worked by hand)', () => {
    // y = x through (10, 10) … (20, 20): it enters the box at its top left corner.
    expect(segmentMeetsBox(0, 0, 40, 40, box)).toBe(true);
    // A line below the box, and one that stops short of it.
    expect(segmentMeetsBox(0, 25, 40, 25, box)).toBe(false);
    expect(segmentMeetsBox(0, 15, 9, 15, box)).toBe(false);
    // A line wholly inside.
    expect(segmentMeetsBox(12, 12, 14, 14, box)).toBe(true);
  });

  it('counts a stroke’s width and a disc’s radius', () => {
    const ink = new Ink();
    ink.segment(0, 24, 40, 24, 1);
    expect(ink.crosses(box)).toBe(false);
    const thick = new Ink();
    thick.segment(0, 24, 40, 24, 4.5);
    expect(thick.crosses(box)).toBe(true);
    const dot = new Ink();
    dot.disc(35, 15, 4);
    expect(dot.crosses(box)).toBe(false);
    dot.disc(35, 15, 6);
    expect(dot.crossing(box)).toMatch(/disc at \(35, 15\)/);
  });

  it('answers at once for a box with an infinite side (the widest of no labels), and finds nothing in it', () => {
    const ink = new Ink();
    ink.segment(0, 15, 40, 15, 1);
    const endless = { x: -Infinity, y: 10, width: -Infinity, height: 10 };
    expect(ink.crosses(endless)).toBe(false);
    expect(ink.hits({ x: NaN, y: 10, width: 20, height: 10 }).strokes).toBe(0);
  });

  it('finds a segment that spans far beyond the screen (a point a million away)', () => {
    const ink = new Ink();
    ink.segment(-1e6, 15, 1e6, 15, 1);
    expect(ink.crosses(box)).toBe(true);
  });

  it('records what the painter strokes, but not a background grid', () => {
    const view = new Viewport();
    view.resize(100, 100);
    view.fit({ minX: 0, minY: 0, maxX: 100, maxY: 100 }, 0, true);
    const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
    painter.polyline([
      [0, 50],
      [100, 50],
    ]);
    const before = painter.ink.segments;
    expect(before).toBe(1);
    painter.polyline(
      [
        [0, 20],
        [100, 20],
      ],
      { role: 'grid' },
    );
    expect(painter.ink.segments).toBe(before);
  });

  it('keeps letters off a geometry grid’s axes, but lets a drawn box cover them', () => {
    // A 200 × 100 figure of x, y in [−1, 3] × [−1, 1]: the origin lands at
    // (50, 50), so the y-axis runs down x = 50.5 and the x-axis across y = 50.5.
    const view = new Viewport();
    view.resize(200, 100);
    view.fit({ minX: -1, minY: -1, maxX: 3, maxY: 1 }, 0, true);
    const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
    painter.grid();
    const onY = { x: 40, y: 10, width: 20, height: 10 };
    const onX = { x: 120, y: 45, width: 30, height: 10 };
    const clear = { x: 120, y: 10, width: 30, height: 10 };
    expect(painter.ink.crosses(onY)).toBe(true);
    expect(painter.ink.crossing(onX)).toMatch(/^the axis/);
    expect(painter.ink.crosses(clear)).toBe(false);
    // A note's box hides the axis under it, as it hides the grid.
    expect(painter.ink.crosses(onY, true)).toBe(false);
    expect(painter.ink.hits(onX).strokes).toBe(0);
  });
});
