import { describe, expect, it } from 'vitest';
import { makeTheme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { drawHeadless, fitFigure, fitPadding, headlineBand } from './headless';
import type { FigureSpec } from './lesson';

const bounds = { minX: 0, minY: 0, maxX: 4, maxY: 1 };
const figure = (headline: boolean): FigureSpec<null, null> => ({
  id: 'f',
  title: 'f',
  kind: 'geometry',
  bounds: () => bounds,
  draw: () => {},
  headline: () => headline,
});

describe('a figure fitted with a heading', () => {
  it('keeps a band of one heading line above the subject, and the padding below it', () => {
    const theme = makeTheme(false, false);
    // A tall box: the width sets the scale, so the subject is centred up and down without a heading.
    for (const headline of [false, true]) {
      const view = new Viewport(400, 300);
      view.resize(400, 300);
      fitFigure(view, figure(headline), null, theme, 20);
      const [, top] = view.toScreen([0, bounds.maxY]);
      const [, foot] = view.toScreen([0, bounds.minY]);
      // Worked by hand: the scale is (400 − 2·20)/4 = 90 px a unit, so the
      // subject is 90 px tall; centred, its top is at (300 − 90)/2 = 105.
      expect(foot - top).toBeCloseTo(90, 6);
      const band = headlineBand(theme);
      expect(top).toBeCloseTo(headline ? 105 + band / 2 : 105, 6);
    }
  });

  it('in a short box, shrinks the subject to leave the band clear at the top', () => {
    const theme = makeTheme(false, true);
    const view = new Viewport(800, 200);
    view.resize(800, 200);
    fitFigure(view, figure(true), null, theme, 20);
    const band = headlineBand(theme);
    const [, top] = view.toScreen([0, bounds.maxY]);
    const [, foot] = view.toScreen([0, bounds.minY]);
    expect(top).toBeCloseTo(20 + band, 6);
    expect(foot).toBeCloseTo(200 - 20, 6);
  });
});

describe('a figure whose marks reach beyond its subject', () => {
  it('keeps at least that much room round the subject, and the padding where that is more', () => {
    const theme = makeTheme(false, false);
    const ringed = (reach: number): FigureSpec<null, null> => ({
      ...figure(false),
      marksReach: () => reach,
    });
    for (const [reach, expected] of [
      [0, 20],
      [35, 35],
    ]) {
      const view = new Viewport(400, 300);
      view.resize(400, 300);
      fitFigure(view, ringed(reach), null, theme, 20);
      // The box is wide: its width sets the scale, so its ends are `expected` px from the sides.
      const [left] = view.toScreen([bounds.minX, 0]);
      const [right] = view.toScreen([bounds.maxX, 0]);
      expect(left).toBeCloseTo(expected, 6);
      expect(400 - right).toBeCloseTo(expected, 6);
    }
  });
});

describe('a plot fitted with rows of values above it', () => {
  // Values of 28 px bold type, measured as a recording measures (0.56 em a
  // character, a subscript 0.78 of the size): "L(t) = 0.00" 11 × 15.68 and
  // its "0" 21.84 × 0.56, 184.7 px; 33.6 px apart; from 11.2 px inside the
  // padding to as far from its other end. A 900 px plot with 30 px padding
  // has 817.6 px for them: three to a row.
  const plot = (count: number): FigureSpec<null, null> => ({
    ...figure(false),
    kind: 'plot',
    cursorValues: () => ({ count, widest: 'L_0(t) = 0.00' }),
  });
  const fitted = (width: number, height: number, count: number) => {
    const view = new Viewport(width, height);
    view.resize(width, height);
    fitFigure(view, plot(count), null, makeTheme(false, true), 30);
    const [, top] = view.toScreen([0, bounds.maxY]);
    const [, foot] = view.toScreen([0, bounds.minY]);
    // The room kept beyond the padding, and the rows the view says it kept.
    return { top, foot, kept: Math.round((top - 30) * 1e6) / 1e6, rows: view.valueRows };
  };
  /** The room `rows` rows take, by hand: the foot's gap 0.25, a box 1.3 + 0.7, a row's pitch 1.95, 2 px; less the padding's 30. */
  const room = (rows: number) => Math.ceil(28 * (0.25 + 2) + (rows - 1) * 28 * 1.95 + 2 - 30);

  it('keeps the rows they take: three values one row over the plot, four one across the figure, five two', () => {
    expect(fitted(900, 500, 3)).toMatchObject({ kept: room(1), rows: 1 });
    // Four take 4 × 184.7 + 3 × 33.6 = 839.6 px: two rows over the plot's
    // 817.6, one across the figure's 900 − 2 × 11.2 = 877.6.
    expect(fitted(900, 500, 4)).toMatchObject({ kept: room(1), rows: 1 });
    // Five take 1,057.9 px: two rows either way.
    const two = fitted(900, 500, 5);
    expect(two).toMatchObject({ kept: room(2), rows: 2 });
    expect(two.top).toBeCloseTo(30 + room(2), 6);
    expect(two.foot).toBeCloseTo(500 - 30, 6);
  });

  it('keeps none on a wide strip they would take more than a quarter of (a phone’s)', () => {
    const { top, foot, kept, rows } = fitted(900, 120, 4);
    expect([kept, rows]).toEqual([0, 0]);
    expect(top).toBeCloseTo(30, 6);
    expect(foot).toBeCloseTo(120 - 30, 6);
  });

  it('keeps a row for each on a plot taller than wide, as long as it stays 0.6 of its width tall', () => {
    // 300 px wide: 217.6 px for them, one to a row; four rows take 199 px of
    // 400, more than a quarter, and leave the plot 201 px ≥ 180 tall.
    expect(fitted(300, 400, 4)).toMatchObject({ kept: room(4), rows: 4 });
    // 340 px tall would leave it 141 px < 180, and a quarter is 85 px: none.
    expect(fitted(300, 340, 4)).toMatchObject({ kept: 0, rows: 0 });
  });
});

describe('a plot’s numbers at its foot', () => {
  // A curve along the plot's floor from end to end: a number pushed up into
  // the plot by too small a foot would lie on it and be left out.
  const floorPlot: FigureSpec<null, null> = {
    id: 'strip',
    title: 'strip',
    kind: 'plot',
    bounds: () => ({ minX: 0, minY: -0.5, maxX: 1, maxY: 1 }),
    draw: (painter) => {
      painter.plotAxes({ minX: 0, minY: -0.5, maxX: 1, maxY: 1 }, 0.1, 0.5);
      painter.polyline(
        [
          [0, -0.5],
          [1, -0.5],
        ],
        { width: 4 },
      );
    },
  };
  const numbersDrawn = (width: number, height: number, projector: boolean) => {
    const theme = makeTheme(false, projector);
    const { svg } = drawHeadless(floorPlot, null, { width, height, theme });
    return svg.texts.filter((t) => /^0\.\d$|^1$|^0$/.test(t));
  };

  it('are all drawn on a 220 px presenter strip (a 1366 × 768 projector), under the curves, not on them', () => {
    // 0.1 … 0.9 by hand ("0" and "1" are y numbers too).
    const texts = numbersDrawn(1340, 220, true);
    for (const n of ['0.1', '0.2', '0.3', '0.4', '0.5', '0.6', '0.7', '0.8', '0.9'])
      expect(texts, n).toContain(n);
  });

  it('leave a phone’s short strip its height: 12% of it at the foot', () => {
    // Type 12 px: 3.2 lines of it (38.4) at the sides; the strip is under six
    // lines (72 px) tall, so its foot and head are 12% of its 60 px.
    const [side, foot] = fitPadding({ kind: 'plot' }, makeTheme(false, false), 340, 60) as number[];
    expect(side).toBeCloseTo(38.4, 9);
    expect(foot).toBeCloseTo(7.2, 9);
  });
});
