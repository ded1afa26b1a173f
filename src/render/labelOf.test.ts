import { describe, expect, it } from 'vitest';
import { glyphBox } from './labels';
import { labelWidth } from './labelWidth';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/** A figure `width` × `height` showing `maxX` × 1 units, its labels held to be placed together. */
function figure(width: number, height: number, maxX: number, svg = new SvgContext()) {
  const view = new Viewport(width, height);
  view.resize(width, height);
  view.fit({ minX: 0, minY: 0, maxX, maxY: 1 }, 0);
  const painter = new Painter(svg, view, makeTheme(false, true));
  painter.holdLabels();
  return { view, painter };
}

/** How far a label's glyphs are from the point (x, y) on screen: 0 if they cover it. */
const gapFrom = (
  box: { x: number; y: number; width: number; height: number },
  x: number,
  y: number,
) =>
  Math.hypot(
    Math.max(box.x - x, 0, x - box.x - box.width),
    Math.max(box.y - y, 0, y - box.y - box.height),
  );

// A point's name whose first place (up and to the right) is crossed by a line
// must stay beside its point: the placer used to shift it a label's width at a
// time, and it stood 109 px from P(u) at the last step of Repeated knots.
describe('a point’s name moved from its first place', () => {
  for (const how of ['label', 'labelClear'] as const)
    it(`goes beside its point, not a label’s width away (${how})`, () => {
      const { view, painter } = figure(600, 400, 1);
      const point = [0.5, 0.5];
      const [x, y] = view.toScreen(point);
      const size = painter.theme.sizes.label;
      // Lines across the first place (10 px up and right) and the rows a
      // label's height above and below it, on both sides, as a crowded
      // polygon's are: the places round the point above and below stay open.
      const height = size * 1.3;
      for (const row of [-height, 0, height]) {
        const ly = y - 10 + row;
        painter.polyline([view.toWorld([x - 8 * size, ly]), view.toWorld([x + 8 * size, ly])], {
          width: 3,
        });
      }
      if (how === 'label') painter.label('B', point, { dx: 10, dy: -10 });
      else painter.labelClear('B', point, []);
      painter.placeLabels();
      const [name] = painter.labels;
      expect(name.text).toBe('B');
      const box = glyphBox(name);
      expect(painter.ink.crossing(box)).toBeNull();
      const gap = gapFrom(box, x, y);
      expect(gap).toBeLessThanOrEqual(size);
    });
});

// A wide name near crowded ink: the shifts to its right ran past the
// figure's edge and were pulled back inside, 170 px from its point, where
// curvature parked "inflection: κ = 0" on the projector with nothing to say
// whose it was. A spot the edge moves far is no spot beside the point.
describe('a name the figure’s edge would carry away from its point', () => {
  it('stays beside it, or is tied to it by a leader', () => {
    const { view, painter } = figure(800, 400, 2);
    const point = [0.75, 0.5];
    const [x, y] = view.toScreen(point);
    // Ink everywhere a label beside the point would stand, and no farther
    // right than x = 440: only a spot pulled back from past the edge is clear.
    for (let ly = 60; ly <= 340; ly += 8)
      painter.polyline([view.toWorld([0, ly]), view.toWorld([440, ly])], { width: 2 });
    painter.label('inflection: κ = 0', point, { dx: 12, dy: -12, bold: true });
    painter.placeLabels();
    const [name] = painter.labels;
    expect(name.text).toBe('inflection: κ = 0');
    const box = glyphBox(name);
    const gap = gapFrom(box, x, y);
    expect(name.leader || gap <= painter.theme.sizes.label).toBe(true);
  });
});

// Surface's P(u,v), put 12 px right of and 18 px below its dot and moved off
// the net: its leader went back to where the label was first put, 75 px to
// the right of the dot and onto another point. A leader ends at the point.
describe('a point’s name sent out on a leader', () => {
  it('is tied to the point it names, not to the place it was first put beside it', () => {
    const svg = new SvgContext();
    const { view, painter } = figure(800, 400, 2, svg);
    const point = [0.75, 0.5];
    const [x, y] = view.toScreen(point);
    for (let ly = 60; ly <= 340; ly += 8)
      painter.polyline([view.toWorld([0, ly]), view.toWorld([440, ly])], { width: 2 });
    // Where the placer starts lines while it places the labels: a leader starts at its point.
    const starts: [number, number][] = [];
    const moveTo = svg.moveTo.bind(svg);
    svg.moveTo = (mx: number, my: number) => {
      starts.push([mx, my]);
      moveTo(mx, my);
    };
    painter.label('inflection: κ = 0', point, { dx: 12, dy: 18, bold: true });
    painter.placeLabels();
    const [name] = painter.labels;
    expect(name.leader).toBe(true);
    expect(starts.some(([sx, sy]) => Math.hypot(sx - x, sy - y) < 0.5)).toBe(true);
  });
});

// bezier-properties' "inflection, u = 0.50": every place round its dot is
// crossed by the curve or the polygon, and the first clear one is a whole
// label's width to the right, 300 px from the dot, with nothing to say whose.
describe('a point’s name shifted a label’s width away', () => {
  it('is tied to its point by a leader', () => {
    const { view, painter } = figure(1200, 600, 2);
    const point = [0.6, 0.5];
    const [x, y] = view.toScreen(point);
    const text = 'inflection, u = 0.50';
    // Ink over every place round the point, out to the right end of where the
    // label is first put: the first place clear is that place shifted right.
    const width = labelWidth(painter, text, { bold: true });
    for (let ly = y - 120; ly <= y + 120; ly += 6)
      painter.polyline([view.toWorld([x - width, ly]), view.toWorld([x + 10 + width + 4, ly])], {
        width: 2,
      });
    painter.label(text, point, { dx: 10, dy: 20, bold: true });
    painter.placeLabels();
    const [name] = painter.labels;
    expect(name.text).toBe(text);
    const box = glyphBox(name);
    const gap = gapFrom(box, x, y);
    expect(gap).toBeGreaterThan(painter.theme.sizes.label * 1.5);
    expect(name.leader).toBe(true);
  });
});

// joins on the projector: the plot's x-axis name "p̄ = i + p", pushed below
// the zero line, stood with p̄'s bar on it: its glyph box was clear of the
// line's stroke by less than a pixel, and the bar stands above the capitals.
describe('a label pushed against a line', () => {
  it('keeps a hair of room above its capitals, for the mark over one', () => {
    const { view, painter } = figure(600, 400, 1);
    const size = painter.theme.sizes.label;
    const [x, y] = view.toScreen([0.5, 0.5]);
    // A line 3 px wide whose lower edge is 0.4 px above the glyph box a label
    // at (x, y) would have: the glyph box alone calls that clear.
    const top = y - size * 0.65 + size * 1.3 * 0.18;
    painter.polyline([view.toWorld([x - 200, top - 1.9]), view.toWorld([x + 400, top - 1.9])], {
      width: 3,
    });
    painter.screenLabel('p̄ = i + p', x, y, { size });
    painter.placeLabels();
    const [name] = painter.labels;
    // Moved: its letters clear of the line's stroke, by more than the hair below it.
    const g = glyphBox(name);
    const [lineTop, lineFoot] = [top - 1.9 - 1.5, top - 1.9 + 1.5];
    expect(g.y + g.height < lineTop || g.y - lineFoot > size * 0.06).toBe(true);
  });
});
