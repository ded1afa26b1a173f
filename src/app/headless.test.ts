import { describe, expect, it } from 'vitest';
import { makeTheme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { fitFigure, headlineBand } from './headless';
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
  const plot = (rows: number): FigureSpec<null, null> => ({
    ...figure(false),
    kind: 'plot',
    valueRows: () => rows,
  });
  const fitted = (height: number, rows: number) => {
    const view = new Viewport(900, height);
    view.resize(900, height);
    fitFigure(view, plot(rows), null, makeTheme(false, true), 30);
    const [, top] = view.toScreen([0, bounds.maxY]);
    const [, foot] = view.toScreen([0, bounds.minY]);
    return { top, foot };
  };

  it('keeps their room over the plot: two rows of 28 px type, by hand', () => {
    // Two rows: the foot's gap 0.25, a box 1.3 + 0.7 and a row's pitch 1.95,
    // at 28 px, and 2 px: 119.6 px, of which the padding gives 30.
    const { top, foot } = fitted(500, 2);
    expect(top).toBeGreaterThanOrEqual(Math.ceil(119.6 - 30) + 30 - 1e-9);
    expect(foot).toBeCloseTo(500 - 30, 6);
  });

  it('keeps none on a strip it would take more than a quarter of (a phone’s)', () => {
    const { top, foot } = fitted(120, 2);
    expect(top).toBeCloseTo(30, 6);
    expect(foot).toBeCloseTo(120 - 30, 6);
  });
});
