import { describe, expect, it } from 'vitest';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/** The opacity of the one filled region a painter draws, read from its SVG. */
function tintOf(projector: boolean, alpha: number): number {
  const svg = new SvgContext();
  const view = new Viewport(200, 200);
  view.resize(200, 200);
  view.fit({ minX: 0, minY: 0, maxX: 1, maxY: 1 }, 10);
  const painter = new Painter(svg, view, makeTheme(false, projector));
  painter.polygon(
    [
      [0, 0],
      [1, 0],
      [0, 1],
    ],
    '#0050A0',
    alpha,
  );
  const fill = svg.elements.find((e) => e.includes('fill="#0050A0"')) ?? '';
  return Number(/opacity="([\d.]+)"/.exec(fill)?.[1] ?? 1);
}

describe('a filled region (a hull, a weight)', () => {
  it('keeps its own pale tint on a screen', () => {
    expect(tintOf(false, 0.12)).toBeCloseTo(0.12, 5);
  });
  it('is at least a quarter opaque on the projector, where a paler tint washes out', () => {
    expect(tintOf(true, 0.12)).toBeCloseTo(0.25, 5);
    // A region already stronger keeps its own.
    expect(tintOf(true, 0.4)).toBeCloseTo(0.4, 5);
  });
});
