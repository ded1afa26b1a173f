import { describe, expect, it } from 'vitest';
import { boxesMeet } from '../render/ink';
import { Painter } from '../render/painter';
import { SvgContext } from '../render/svgContext';
import { makeTheme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { plotYName, valueColumn } from './plotMarks';

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

describe('a plot’s y-axis name with the labels hidden (presenter key A)', () => {
  it('is not drawn', () => {
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
    painter.placeLabels();
    expect(painter.labels).toEqual([]);
    expect(svg.elements.join('')).not.toContain('W(N');
  });
});

describe('the values at a plot’s cursor', () => {
  it('on a phone’s short strip, no two of their boxes overlap and none crosses the cursor’s line', () => {
    // b-splines' NURBS basis on a phone (344 × 90): four values, a row too
    // wide for the strip; two were boxed a line apart and their boxes crossed
    // the subscripts above them (N₂,₃ over N₃,₃).
    for (const projector of [false, true])
      for (const [width, height] of [
        [344, 90],
        [344, 120],
        [600, 90],
      ]) {
        const view = new Viewport(width, height);
        view.resize(width, height);
        const bounds = { minX: 0, minY: 0, maxX: 1, maxY: 1.05 };
        view.fit(bounds, [30, 20], false);
        const painter = new Painter(new SvgContext(), view, makeTheme(false, projector));
        const entries = [
          'N_{2,3} = 0.588',
          'N_{1,3} = 0.128',
          'N_{3,3} = 0.283',
          'N_{4,3} = 0.001',
        ].map((text) => ({ text, color: '#000' }));
        valueColumn(painter, 0.3, bounds, 0, entries);
        const boxes = painter.labels.map((b) => ({ text: b.text, edge: b.frame ?? b }));
        expect(boxes.length, `${width} × ${height}`).toBeGreaterThan(0);
        // Nor does one cross the cursor's line, whose dots they are the values of.
        const [cursorX] = view.toScreen([0.3, 0]);
        for (const { text, edge } of boxes)
          expect(
            edge.x < cursorX && cursorX < edge.x + edge.width,
            `${width} × ${height}: “${text}” across the cursor`,
          ).toBe(false);
        for (const [i, a] of boxes.entries())
          for (const b of boxes.slice(i + 1))
            expect(
              boxesMeet(a.edge, b.edge),
              `${width} × ${height}: “${a.text}” and “${b.text}”`,
            ).toBe(false);
      }
  });
});
