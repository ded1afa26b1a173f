import { describe, expect, it } from 'vitest';
import type { FigureSpec, LayoutNode } from './lesson';
import { fittedScale, layoutFor } from './tallLayout';
import { makeTheme } from '../render/theme';

// Worked by hand for presenter view's theme (handles 14 px, labels 36 px):
// a figure in the plane is padded by min(2 · 14 + 1.6 · 36, 0.12 · its
// smaller side) = min(85.6, 0.12 · side). In a 1900 × 840 area with 8 px
// gaps, a column of two gives each 1900 × 416 (padding 49.92), a row of two
// each 946 × 840 (padding 85.6).
const theme = makeTheme(false, true);
const AREA = { width: 1900, height: 840 };
const TALL: LayoutNode = { row: ['curve', 'plot'] };

function curve(width: number, height: number): FigureSpec<null, null> {
  return {
    id: 'curve',
    title: 'curve',
    kind: 'geometry',
    bounds: () => ({ minX: 0, maxX: width, minY: 0, maxY: height }),
    draw: () => {},
  };
}
const plot: FigureSpec<null, null> = {
  id: 'plot',
  title: 'plot',
  kind: 'plot',
  bounds: () => ({ minX: 0, maxX: 1, minY: 0, maxY: 1 }),
  draw: () => {},
};

function chosen(figures: FigureSpec<null, null>[], area = AREA, tall = TALL) {
  return layoutFor({ layout: 'column', tallLayout: tall, figures }, figures, null, area, theme);
}

describe('presenter view arranges a scene for its subject', () => {
  it('a figure in the plane is fitted with the page’s padding: its scale in pixels per unit', () => {
    // min((1900 − 99.84) / 1, (416 − 99.84) / 2) = 158.08.
    expect(fittedScale(curve(1, 2), null, 1900, 416, theme)).toBeCloseTo(158.08, 6);
    // min((946 − 171.2) / 1, (840 − 171.2) / 2) = 334.4.
    expect(fittedScale(curve(1, 2), null, 946, 840, theme)).toBeCloseTo(334.4, 6);
  });

  it('a subject twice as tall as wide takes the plot beside it (158.08 → 334.4 px per unit)', () => {
    expect(chosen([curve(1, 2), plot])).toBe(TALL);
  });

  it('a wide subject keeps the plot under it (316.16 px per unit would fall to 258.27)', () => {
    expect(chosen([curve(3, 1), plot])).toBe('column');
  });

  it('only a clear gain changes the arrangement: 1.2 times, no less', () => {
    // Beside: 774.8 px per unit (width-limited); under: 316.16 / h. Gain 2.4507 h.
    expect(chosen([curve(1, 0.47), plot])).toBe('column'); // gain 1.15
    expect(chosen([curve(1, 0.51), plot])).toBe(TALL); // gain 1.25
  });

  it('no plot is squeezed under 420 px wide to make room: on a narrow screen the plot stays under', () => {
    // 800 px wide: side by side each would be 396 px; stacked each is 800 × 416.
    expect(chosen([curve(1, 2), plot], { width: 800, height: 840 })).toBe('column');
  });

  it('a view in space keeps at least 90% of its size', () => {
    const space: FigureSpec<null, null> = { ...plot, id: 'space', kind: 'space' };
    const figures = [curve(1, 2), space, plot];
    const lesson = (tall: LayoutNode) => ({
      layout: { column: [{ row: ['curve', 'space'] }, 'plot'] } as LayoutNode,
      tallLayout: tall,
      figures,
    });
    const keeps: LayoutNode = { row: ['curve', { column: ['space', 'plot'] }] };
    const shrinks: LayoutNode = { row: ['curve', { column: ['space', 'plot'], weights: [1, 2] }] };
    // Under: space 946 × 416. Beside, weights 1 : 1: 946 × 416 (kept); 1 : 2: 946 × 277.3 (67%).
    expect(layoutFor(lesson(keeps), figures, null, AREA, theme)).toBe(keeps);
    expect(layoutFor(lesson(shrinks), figures, null, AREA, theme)).toEqual(lesson(shrinks).layout);
  });

  it('a lesson without a tall layout keeps its own', () => {
    const figures = [curve(1, 2), plot];
    expect(layoutFor({ layout: 'column', figures }, figures, null, AREA, theme)).toBe('column');
  });
});
