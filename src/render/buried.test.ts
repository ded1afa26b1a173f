import { describe, expect, it } from 'vitest';
import { subjectUnderHandles } from './buried';
import { drawHandles } from './handles';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

// A road through many villages: a line from (0, 0) to (100, 0) drawn 1000 px
// long and 16.8 px wide, with a village every 10 px. At the projector's sizes
// a full handle is 14 px in radius, a small one 7 px, each with a 5.4 px
// outline: either covers the road's whole width along its whole length. A dot
// (3.5 px, a 2 px outline) is narrower than the road, which shows on either
// side of it.

const theme = makeTheme(false, true);
/** The road's surface in presenter view: 2.4 curves wide. */
const WIDTH = theme.sizes.curve * 2.4;

function road(handle: { small?: boolean; dot?: boolean }, every = 1) {
  const view = new Viewport(1100, 300);
  view.resize(1100, 300);
  view.fit({ minX: 0, minY: -10, maxX: 100, maxY: 10 }, 50);
  const painter = new Painter(new SvgContext(), view, theme);
  painter.polyline(
    [
      [0, 0],
      [100, 0],
    ],
    { role: 'curve', width: WIDTH },
  );
  const villages = Array.from({ length: 100 / every + 1 }, (_, i) => ({
    id: `p${i}`,
    label: `P_{${i}}`,
    position: [i * every, 0],
    showLabel: false,
    ...handle,
  }));
  drawHandles(painter, villages);
  return painter;
}

describe('a curve under its handles', () => {
  it('is all hidden by full or half-size handles 10 px apart', () => {
    expect(subjectUnderHandles(road({}).ink)).toBeCloseTo(1, 2);
    expect(subjectUnderHandles(road({ small: true }).ink)).toBeCloseTo(1, 2);
  });

  it('is not hidden by dots narrower than it', () => {
    expect(subjectUnderHandles(road({ dot: true }).ink)).toBe(0);
  });

  it('is hidden in proportion where handles stand apart', () => {
    // Handles every 100 px, 14 px in radius with a 5.4 px outline (16.7 px
    // to its outer edge): the road's whole width is covered where
    // |d| < √(16.7² − 8.4²) = 14.43 px of a centre: 28.9 px of every 100.
    // Sampled every pixel: to within a pixel at each edge of each handle.
    expect(Math.abs(subjectUnderHandles(road({}, 10).ink) - 0.289)).toBeLessThan(0.011);
  });

  it('is nothing when the figure has no subject', () => {
    const painter = road({});
    expect(subjectUnderHandles(new Painter(new SvgContext(), painter.view, theme).ink)).toBe(0);
  });
});
