import { describe, expect, it } from 'vitest';
import { boxesMeet } from '../render/ink';
import { Painter } from '../render/painter';
import { SvgContext } from '../render/svgContext';
import { makeTheme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { valueColumn } from './cursorValues';
import { valueBand } from './valueRows';
import { lineName, plotYName } from './plotMarks';

/**
 * A 900 × 300 plot of [0, 1] × [0, 1.2] with its y name; `starts` draws a
 * basis that starts at 1 by the axis and falls away, as B₀, H₀ and L₀ do.
 */
function yNameBox(starts: boolean) {
  const view = new Viewport(900, 300);
  view.resize(900, 300);
  const bounds = { minX: 0, minY: 0, maxX: 1, maxY: 1.2 };
  view.fit(bounds, [90, 40], false);
  const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
  painter.holdLabels();
  const top = plotYName(painter, bounds, 'W(N, i, μ)');
  if (starts)
    painter.polyline(
      Array.from({ length: 41 }, (_, i) => [i / 40, 1.2 * (1 - i / 40) ** 3] as [number, number]),
      { width: 3 },
    );
  painter.placeLabels();
  const box = painter.labels.find((b) => b.text === 'W(N, i, μ)')!;
  return { box, top, painter };
}

describe('a plot’s y-axis name', () => {
  it('sits by the axis at the top when nothing is drawn there', () => {
    const { box, top } = yNameBox(false);
    const [axis, head] = [90, 40];
    expect(box.x - axis).toBeGreaterThan(0);
    expect(box.x - axis).toBeLessThan(40);
    expect(box.y).toBeGreaterThan(head - 10);
    // The values' column starts below it.
    expect(top).toBeGreaterThan(box.y + box.height - 5);
  });
  it('moves along the top, clear of a basis that starts at 1 by the axis', () => {
    const { box, painter } = yNameBox(true);
    expect(box.x).toBeGreaterThan(150);
    expect(painter.ink.hits(box)).toEqual({ discs: 0, strokes: 0 });
  });
});

describe('a plot’s y-axis name, values and line names with the labels hidden (presenter key A)', () => {
  it('are not drawn', () => {
    const view = new Viewport(900, 300);
    view.resize(900, 300);
    const bounds = { minX: 0, minY: 0, maxX: 1, maxY: 1.2 };
    view.fit(bounds, [90, 40], false);
    const svg = new SvgContext();
    const painter = new Painter(svg, view, makeTheme(false, false), {
      curve: true,
      labels: false,
      numbers: true,
    });
    painter.holdLabels();
    plotYName(painter, bounds, 'W(N, i, μ)');
    // Nor the values at the cursor, nor a line's name.
    valueColumn(painter, 0.3, bounds, 40, [{ text: 'κ = 0.5', color: '#000' }]);
    lineName(painter, 0.5, bounds, 'C²');
    painter.placeLabels();
    expect(painter.labels).toEqual([]);
    expect(svg.elements.join('')).not.toContain('W(N');
    expect(svg.texts).toEqual([]);
  });
});

/** A phone's short basis strip of [0, 1] × [0, 1.05], `width` × `height`, in screen or projector type. */
function phoneStrip(width: number, height: number, projector: boolean) {
  const view = new Viewport(width, height);
  view.resize(width, height);
  const bounds = { minX: 0, minY: 0, maxX: 1, maxY: 1.05 };
  view.fit(bounds, [30, 20], false);
  return {
    view,
    bounds,
    painter: new Painter(new SvgContext(), view, makeTheme(false, projector)),
  };
}

/** b-splines' four values at the cursor on its NURBS basis. */
const FOUR_VALUES = [
  'N_{2,3} = 0.588',
  'N_{1,3} = 0.128',
  'N_{3,3} = 0.283',
  'N_{4,3} = 0.001',
].map((text) => ({ text, color: '#000' }));

describe('the values at a plot’s cursor', () => {
  it('on a phone’s short strip, no two of their boxes overlap, none crosses the cursor’s line, all stand inside', () => {
    // b-splines' NURBS basis on a phone (344 × 90): four values, a row too
    // wide for the strip; two were boxed a line apart and their boxes crossed
    // the subscripts above them (N₂,₃ over N₃,₃).
    for (const projector of [false, true])
      for (const [width, height] of [
        [344, 90],
        [344, 120],
        [600, 90],
      ]) {
        const { view, bounds, painter } = phoneStrip(width, height, projector);
        valueColumn(painter, 0.3, bounds, 0, FOUR_VALUES);
        const boxes = painter.labels.map((b) => ({ text: b.text, edge: b.frame ?? b }));
        // A phone's type finds room for some (projector type on a phone-sized
        // strip may find none: then none is drawn over the plot).
        if (!projector) expect(boxes.length, `${width} × ${height}`).toBeGreaterThan(0);
        // Nor does one cross the cursor's line, whose dots they are the values of.
        const [cursorX] = view.toScreen([0.3, 0]);
        for (const { text, edge } of boxes) {
          expect(
            edge.x < cursorX && cursorX < edge.x + edge.width,
            `${width} × ${height}: “${text}” across the cursor`,
          ).toBe(false);
          const inside =
            edge.x >= 0 &&
            edge.y >= 0 &&
            edge.x + edge.width <= width &&
            edge.y + edge.height <= height;
          expect(inside, `${width} × ${height}: “${text}” inside`).toBe(true);
        }
        for (const [i, a] of boxes.entries())
          for (const b of boxes.slice(i + 1))
            expect(
              boxesMeet(a.edge, b.edge),
              `${width} × ${height}: “${a.text}” and “${b.text}”`,
            ).toBe(false);
      }
  });

  it('on a phone’s short strip, leaves out a value whose box a curve would run under', () => {
    // A 344 × 90 strip with a curve across its top, at y = 1 from x = 0.5 on:
    // the values left of it stand, those over it are left out, not laid over it.
    const { view, bounds, painter } = phoneStrip(344, 90, false);
    painter.holdLabels();
    const across = Array.from({ length: 41 }, (_, i) => [0.5 + i / 80, 1]).flat();
    painter.polylineFlat(across, { color: '#000', width: 2 });
    valueColumn(painter, 0.05, bounds, 0, FOUR_VALUES);
    painter.placeLabels();
    const [curveX] = view.toScreen([0.5, 0]);
    const placed = painter.labels.map((b) => b.frame ?? b);
    expect(placed.length).toBeGreaterThan(0);
    expect(placed.length).toBeLessThan(FOUR_VALUES.length);
    for (const box of placed) expect(box.x + box.width).toBeLessThan(curveX);
  });
});

/** A 900 × 300 plot of [0, 4] × [−1, 3], its labels held as the page holds them. */
function strip(width = 900, height = 300, top = 30) {
  const view = new Viewport(width, height);
  view.resize(width, height);
  const bounds = { minX: 0, minY: -1, maxX: 4, maxY: 3 };
  view.fit(bounds, [60, top], false);
  const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
  painter.holdLabels();
  return { view, bounds, painter };
}

/** A peak of height 3 at x = `at`, 0.1 wide, as κ peaks where a spline bends hard. */
const peak = (at: number): [number, number][] =>
  Array.from({ length: 41 }, (_, i) => {
    const x = at - 0.5 + i / 40;
    return [x, 3 * Math.exp(-(((x - at) / 0.12) ** 2))];
  });

describe('the values at a plot’s cursor, in a column', () => {
  it('move off a peak that runs up under the far corner, and stay on their side of the cursor', () => {
    const { view, bounds, painter } = strip();
    painter.polyline(peak(3.7), { width: 3 });
    const entries = [{ text: 'κ = −0.974', color: '#000' }];
    valueColumn(painter, 1.8, bounds, 20, entries);
    painter.placeLabels();
    const [box] = painter.labels;
    const edge = box.frame ?? box;
    // Worked by hand: the corner away from the cursor is the right one; the
    // peak at 3.7 is under it, so the box moves left, and not past 1.8.
    expect(painter.ink.crosses(edge)).toBe(false);
    expect(edge.x).toBeGreaterThan(view.toScreen([1.8, 0])[0]);
    expect(edge.x + edge.width).toBeLessThan(view.toScreen([3.7, 0])[0]);
  });

  it('where every place is crossed, never stay over another label: they go where the placer finds room', () => {
    // joins on a phone: the y-axis name boxed along the top, the curve's
    // peaks under the rest; the value was left boxed over the name.
    const { bounds, painter } = strip(360, 140);
    for (const at of [0.6, 1.6, 2.6, 3.6]) painter.polyline(peak(at), { width: 3 });
    painter.screenLabel('κ, κ of Catmull-Rom, κ of a natural one', 4, 14, {
      box: true,
      fixed: true,
    });
    valueColumn(painter, 2, bounds, 8, [{ text: 'κ = −0.462', color: '#000' }]);
    painter.placeLabels();
    expect(painter.labels.map((b) => b.text)).toContain('κ = −0.462');
    const [a, b] = painter.labels.map((l) => l.frame ?? l);
    expect(boxesMeet(a, b)).toBe(false);
  });

  it('with no values (every one off the plot) draw nothing, and return', () => {
    const { bounds, painter } = strip();
    valueColumn(painter, 2, bounds, 20, []);
    painter.placeLabels();
    expect(painter.labels).toEqual([]);
  });
});

describe('the values at a plot’s cursor, above the plot', () => {
  /** A 1900 × 330 strip (presenter view's) fitted as the page fits one with a row of values, four peaks up to 3. */
  function banded(width = 1900, rows = 1) {
    const view = new Viewport(width, 330);
    view.resize(width, 330);
    const bounds = { minX: 0, minY: -1, maxX: 4, maxY: 3 };
    const theme = makeTheme(false, true);
    const band = valueBand(theme, rows, 30);
    view.fit(bounds, [60, 30 + band / 2], false);
    view.panBy(0, band / 2);
    view.valueRows = rows;
    const painter = new Painter(new SvgContext(), view, theme);
    painter.holdLabels();
    for (const at of [0.5, 1.5, 2.5, 3.5]) painter.polyline(peak(at), { width: 3 });
    return { view, bounds, painter };
  }
  const entries = ['L₀(t) = 0.12', 'L₁(t) = −0.36', 'L₂(t) = 0.81', 'L₃(t) = 0.43'].map((text) => ({
    text,
    color: '#000',
  }));

  it('stand in a row over the plot’s top, in order, over no curve', () => {
    const { view, bounds, painter } = banded();
    const plotTop = view.toScreen([0, bounds.maxY])[1];
    valueColumn(painter, 2, bounds, plotTop, entries);
    painter.placeLabels();
    const boxes = entries.map(({ text }) => painter.labels.find((l) => l.text === text)!);
    for (const box of boxes) {
      const edge = box.frame ?? box;
      expect(edge.y + edge.height, box.text).toBeLessThan(plotTop);
      expect(edge.y, box.text).toBeGreaterThanOrEqual(0);
      expect(painter.ink.crosses(edge), box.text).toBe(false);
    }
    // One row, left to right as given.
    expect(new Set(boxes.map((b) => Math.round(b.y))).size).toBe(1);
    expect(boxes.map((b) => b.x)).toEqual([...boxes.map((b) => b.x)].sort((a, b) => a - b));
  });

  it('start right of a label already at the rows’ start (the plot’s y name), and stay in one row', () => {
    const { view, bounds, painter } = banded();
    const plotTop = view.toScreen([0, bounds.maxY])[1];
    // A y name at the axis' top, across the plot's top edge as plotAxes
    // sets it, placed before the values.
    painter.screenLabel('κ(t)', 80, plotTop - 4, { size: 28, fixed: true });
    valueColumn(painter, 2, bounds, plotTop, entries);
    painter.placeLabels();
    const name = painter.labels.find((l) => l.text === 'κ(t)')!;
    const values = entries.map(({ text }) => painter.labels.find((l) => l.text === text)!);
    for (const box of values) {
      expect(box.x, box.text).toBeGreaterThan(name.x + name.width);
      expect(box.y + box.height, box.text).toBeLessThan(plotTop);
    }
  });

  it('wrap to rows where the plot is narrow, still above it; with no room, go in the plot', () => {
    const narrow = banded(700, 2);
    const plotTop = narrow.view.toScreen([0, narrow.bounds.maxY])[1];
    valueColumn(narrow.painter, 2, narrow.bounds, plotTop, entries);
    narrow.painter.placeLabels();
    const rows = new Set(narrow.painter.labels.map((b) => Math.round(b.y)));
    expect(rows.size).toBe(2);
    for (const box of narrow.painter.labels) expect(box.y + box.height).toBeLessThan(plotTop);
    // No band: the plot's top 20 px from the figure's, too little for a row.
    const { view, bounds, painter } = strip(1900, 330, 20);
    const top = view.toScreen([0, bounds.maxY])[1];
    valueColumn(painter, 2, bounds, top, entries);
    painter.placeLabels();
    expect(painter.labels).toHaveLength(4);
    for (const box of painter.labels) expect(box.y + box.height / 2).toBeGreaterThan(top);
  });
});

describe('the name of a line across a plot', () => {
  const lines = (painter: Painter, bounds: { minY: number; maxY: number }, xs: number[]) => {
    for (const x of xs)
      painter.polyline(
        [
          [x, bounds.minY],
          [x, bounds.maxY],
        ],
        { width: 1.5, dash: [4, 4] },
      );
  };

  it('sits against its own line, on its right, or on its left at the plot’s right end', () => {
    const { view, bounds, painter } = strip();
    lines(painter, bounds, [1, 4]);
    lineName(painter, 1, bounds, 'C²');
    lineName(painter, 4, bounds, 'κ = 0');
    painter.placeLabels();
    const named = (text: string) => painter.labels.find((b) => b.text === text)!;
    const [one] = view.toScreen([1, 0]);
    const [four] = view.toScreen([4, 0]);
    const c2 = named('C²');
    expect(c2.x).toBeGreaterThan(one);
    expect(c2.x - one).toBeLessThan(15);
    const end = named('κ = 0');
    expect(end.x + end.width).toBeLessThan(four);
    expect(four - (end.x + end.width)).toBeLessThan(15);
  });

  it('finds a clear height beside its line, off the curve and off the other names', () => {
    const { bounds, painter } = strip();
    lines(painter, bounds, [3, 3.5]);
    painter.polyline(peak(3.08), { width: 3 });
    lineName(painter, 3, bounds, 'C²');
    lineName(painter, 3.5, bounds, 'κ = 0');
    painter.placeLabels();
    expect(painter.labels.map((b) => b.text).sort()).toEqual(['C²', 'κ = 0']);
    for (const b of painter.labels) expect(painter.ink.crossing(b), b.text).toBeNull();
    const [a, b] = painter.labels;
    expect(boxesMeet(a, b)).toBe(false);
  });

  it('goes unnamed where there is no room beside it, rather than beside another line', () => {
    // Lines 19.5 px apart (195 px to a unit): "middle" crosses a line on
    // either side of its own, at every height, so it is left out; "first"
    // would cross the middle line on its right, so it is named on its left;
    // "last" on its right. Worked by hand from the widths (each > 19.5 px).
    const { view, bounds, painter } = strip(900, 120);
    const xs = [2, 2.1, 2.2];
    lines(painter, bounds, xs);
    xs.forEach((x, i) => lineName(painter, x, bounds, ['first', 'middle', 'last'][i]));
    painter.placeLabels();
    expect(painter.labels.map((b) => b.text).sort()).toEqual(['first', 'last']);
    for (const b of painter.labels) expect(painter.ink.crossing(b), b.text).toBeNull();
    const [a, , c] = xs.map((x) => view.toScreen([x, 0])[0]);
    const first = painter.labels.find((b) => b.text === 'first')!;
    const last = painter.labels.find((b) => b.text === 'last')!;
    expect(a - (first.x + first.width)).toBeGreaterThan(0);
    expect(a - (first.x + first.width)).toBeLessThan(15);
    expect(last.x - c).toBeGreaterThan(0);
    expect(last.x - c).toBeLessThan(15);
  });
});
