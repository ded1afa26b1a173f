import { describe, expect, it } from 'vitest';
import { presenterSizes } from './figureSizes';

// Sizes worked by hand, and checked against the page: curvature at
// 1920 × 1080 in presenter view measured 1137 × 551, 759 × 551 and
// 1904 × 370 in a 1904 × 929 box (3 : 2 both ways, an 8 px gap).
const AREA = { width: 1900, height: 840 };

describe('presenter view’s figure sizes without a browser', () => {
  it('a column of a row (weights 3 : 2) and a plot, as curvature lays them out', () => {
    const sizes = presenterSizes(
      { column: [{ row: ['curve', 'space'] }, 'plot'], weights: [3, 2] },
      [{ id: 'curve', weight: 3 }, { id: 'space', weight: 2 }, { id: 'plot' }],
      AREA,
      1,
    );
    // Height: (840 − 8) × 3/5 = 499.2 and × 2/5 = 332.8; width: (1900 − 8) × 3/5 = 1135.2, × 2/5 = 756.8.
    expect(sizes.get('curve')).toEqual({ width: 1135.2, height: 499.2 });
    expect(sizes.get('space')).toEqual({ width: 756.8, height: 499.2 });
    expect(sizes.get('plot')).toEqual({ width: 1900, height: 332.8 });
  });
  it('a strip of fixed height takes its own, scaled, and the figure above it the rest', () => {
    const sizes = presenterSizes(
      'column',
      [{ id: 'main' }, { id: 'strip', height: 100 }],
      AREA,
      1.5,
    );
    expect(sizes.get('strip')).toEqual({ width: 1900, height: 150 });
    expect(sizes.get('main')).toEqual({ width: 1900, height: 840 - 8 - 150 });
  });
  it('a figure the step hides takes no room: its row gives the others its share', () => {
    const sizes = presenterSizes(
      { row: ['curve', { column: ['basis', 'knots'] }], weights: [1.8, 1] },
      [{ id: 'curve' }],
      AREA,
      1,
    );
    expect(sizes.get('curve')).toEqual({ width: 1900, height: 840 });
    expect(sizes.has('basis')).toBe(false);
  });
  it('a grid shares both ways evenly', () => {
    const sizes = presenterSizes(
      {
        grid: {
          columns: ['C⁰', 'C¹'],
          rows: ['a', 'b'],
          cells: [
            ['p', 'q'],
            ['r', 's'],
          ],
        },
      },
      ['p', 'q', 'r', 's'].map((id) => ({ id })),
      AREA,
      1,
    );
    expect(sizes.get('s')).toEqual({ width: (1900 - 8) / 2, height: (840 - 8) / 2 });
  });
});
