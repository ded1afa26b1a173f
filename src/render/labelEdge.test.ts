import { describe, expect, it } from 'vitest';
import { boxesMeet } from './ink';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/**
 * A 400 × 200 figure ruled with strokes every 8 px, so no place is clear: a
 * label is boxed where it lands, and the box too stays inside the figure.
 */
function ruled(box: boolean) {
  const view = new Viewport(400, 200);
  view.fit({ minX: 0, minY: 0, maxX: 400, maxY: 200 }, 0);
  const svg = new SvgContext();
  const theme = makeTheme(false, true);
  const painter = new Painter(svg, view, theme);
  for (let y = 4; y < 200; y += 8) painter.segment([0, y], [400, y], { width: 2 });
  const before = svg.elements.length;
  painter.screenLabel('frame flips: κ → 0', 390, 100, { bold: true, ...(box ? { box } : {}) });
  const rects = svg.elements
    .slice(before)
    .filter((e) => e.startsWith('<rect'))
    .map((e) => {
      const at = (name: string) => Number(new RegExp(`${name}="([-\\d.]+)"`).exec(e)![1]);
      return { x: at('x'), y: at('y'), width: at('width'), height: at('height') };
    });
  return { rects, label: painter.labels.at(-1)! };
}

describe('a label near the edge', () => {
  for (const box of [false, true])
    it(`keeps its box inside the figure (${box ? 'asked for' : 'given where nothing is clear'})`, () => {
      const { rects, label } = ruled(box);
      expect(label.boxed).toBe(true);
      expect(rects.length).toBeGreaterThan(0);
      for (const r of rects) {
        expect(r.x).toBeGreaterThanOrEqual(0);
        expect(r.x + r.width).toBeLessThanOrEqual(400);
        expect(r.y).toBeGreaterThanOrEqual(0);
        expect(r.y + r.height).toBeLessThanOrEqual(200);
      }
    });
});

describe('a label said elsewhere too (optional)', () => {
  it('is left out where no place near it is clear, and drawn where one is', () => {
    const view = new Viewport(400, 200);
    view.fit({ minX: 0, minY: 0, maxX: 400, maxY: 200 }, 0);
    const svg = new SvgContext();
    const painter = new Painter(svg, view, makeTheme(false, false));
    // Ruled every 8 px over the left half only (a label 15 px high, about 140 px long).
    for (let y = 4; y < 200; y += 8) painter.segment([0, y], [200, y], { width: 2 });
    painter.screenLabel('u then v = v then u', 20, 100, { optional: true });
    expect(painter.labels).toEqual([]);
    expect(svg.elements.some((e) => e.includes('u then v'))).toBe(false);
    painter.screenLabel('u then v = v then u', 240, 100, { optional: true });
    expect(painter.labels.map((l) => l.text)).toEqual(['u then v = v then u']);
    expect(painter.labels[0].boxed).toBeUndefined();
  });
});

describe('a leader line', () => {
  /** A 400 × 300 figure whose top 64 px are ruled every 8 px, and clear below. */
  function topRuled() {
    const view = new Viewport(400, 300);
    view.fit({ minX: 0, minY: 0, maxX: 400, maxY: 300 }, 0);
    const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
    // World y grows upwards: the ruled band is the screen's top 64 px, as far
    // as the near places reach (two lines up or down); the far ones reach past it.
    for (let y = 236; y < 300; y += 8) painter.segment([0, y], [400, y], { width: 2 });
    return painter;
  }
  it('ties a point’s name back to its point when the name must go farther out', () => {
    const painter = topRuled();
    painter.label('P_3', [60, 280], { dx: 6, dy: -6 });
    const name = painter.labels.at(-1)!;
    expect(name.leader, JSON.stringify(name)).toBe(true);
  });
  it('never hangs a heading, which names no point, from a leader to nowhere', () => {
    // Raster's "Uniform, planned: 14 segments" went down a leader from its corner on a phone.
    const painter = topRuled();
    painter.screenLabel('Uniform, planned: 14 segments', 10, 20, { bold: true, halo: true });
    const heading = painter.labels.at(-1)!;
    expect(heading.leader, JSON.stringify(heading)).toBeUndefined();
    // It went where it is clear, below the ruled band.
    expect(heading.y, JSON.stringify(heading)).toBeGreaterThan(60);
  });
});

describe('boxed labels', () => {
  it('keep their boxes apart, not only their letters: two asked at one spot are stacked a box apart', () => {
    for (const projector of [false, true]) {
      const view = new Viewport(400, 200);
      view.fit({ minX: 0, minY: 0, maxX: 400, maxY: 200 }, 0);
      const painter = new Painter(new SvgContext(), view, makeTheme(false, projector));
      painter.screenLabel('N_{2,3} = 0.588', 100, 100, { bold: true, box: true });
      painter.screenLabel('N_{3,3} = 0.283', 100, 100, { bold: true, box: true });
      const [a, b] = painter.labels;
      expect(a.frame && b.frame, 'both boxed').toBeTruthy();
      expect(
        boxesMeet(a.frame!, b.frame!),
        `${JSON.stringify(a.frame)} and ${JSON.stringify(b.frame)}`,
      ).toBe(false);
    }
  });
});
