import { describe, expect, it } from 'vitest';
import { leastHidden } from './boxPlaces';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/** A 600 × 400 figure of the unit square, its labels held back until placed. */
function unitSquare() {
  const view = new Viewport(600, 400);
  view.resize(600, 400);
  view.fit({ minX: 0, minY: 0, maxX: 1, maxY: 1 }, 0);
  const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
  painter.holdLabels();
  return { view, painter };
}

/** A 600 × 400 figure of the unit square, a stroke through the part of it `stroke` names. */
function noteBox(stroke: 'top left' | 'top' | 'none', top?: number) {
  const { painter } = unitSquare();
  // y = 1 is the top edge; a line a little below it, across the left third or the whole width.
  if (stroke !== 'none')
    painter.polyline(
      [
        [0, 0.97],
        [stroke === 'top' ? 1 : 0.35, 0.97],
      ],
      { width: 3 },
    );
  painter.note('Both velocities are zero here: the curvature is undefined', { top });
  painter.placeLabels();
  return painter.labels.find((b) => b.text.startsWith('Both'))!;
}

describe('a figure’s note', () => {
  it('sits at the top left when nothing is drawn there', () => {
    const box = noteBox('none');
    expect(box.x).toBeLessThan(20);
    expect(box.y).toBeLessThan(20);
  });
  it('takes the top right when a line runs through the top left', () => {
    const box = noteBox('top left');
    expect(box.x + box.width).toBeGreaterThan(580);
    expect(box.y).toBeLessThan(20);
  });
  it('goes to the foot when a line runs across the whole top', () => {
    const box = noteBox('top');
    expect(box.y + box.height).toBeGreaterThan(380);
  });
  it('stays where it is told when given its top (notes stacked one under another)', () => {
    const box = noteBox('top', 50);
    expect(box.y).toBe(50);
    expect(box.x).toBeLessThan(20);
  });
  it('when no corner is clear, hides no point if a corner with only strokes is left', () => {
    const { view, painter } = unitSquare();
    // Lines across the whole top and the whole foot: every corner is crossed.
    for (const y of [0.97, 0.03])
      painter.polyline(
        [
          [0, y],
          [1, y],
        ],
        { width: 3 },
      );
    // Lines down the middle of both sides: the middle of a side is crossed too.
    for (const x of [0.02, 0.98])
      painter.polyline(
        [
          [x, 0.3],
          [x, 0.7],
        ],
        { width: 3 },
      );
    // A point in the top left, the first corner tried; more strokes in the foot's right.
    painter.dot([0.05, 0.96], '#000', 8);
    for (const y of [0.05, 0.07, 0.09])
      painter.polyline(
        [
          [0.6, y],
          [1, y],
        ],
        { width: 3 },
      );
    painter.note('Both velocities are zero here: the curvature is undefined');
    painter.placeLabels();
    const box = painter.labels.find((b) => b.text.startsWith('Both'))!;
    const [px, py] = view.toScreen([0.05, 0.96]);
    const covers =
      px > box.x - 8 && px < box.x + box.width + 8 && py > box.y - 8 && py < box.y + box.height + 8;
    expect(covers).toBe(false);
    // Of the three corners left, the one crossed by fewest strokes: top right or foot left (one each).
    expect(box.x + box.width > 580 || box.y + box.height > 380).toBe(true);
    expect(box.x + box.width > 580 && box.y + box.height > 380).toBe(false);
  });
  it('wraps narrower and taller to find a clear corner beside the subject', () => {
    const { view, painter } = unitSquare();
    // Points in the middle two fifths, near the top and the foot: a wide note hides one in any corner.
    const points: [number, number][] = [
      [0.4, 0.85],
      [0.6, 0.85],
      [0.4, 0.15],
      [0.6, 0.15],
    ];
    for (const p of points) painter.dot(p, '#000', 8);
    painter.note(
      'Both velocities are zero here: the ratio, the angle and the curvature are undefined',
    );
    painter.placeLabels();
    const box = painter.labels.find((b) => b.text.startsWith('Both'))!;
    for (const p of points) {
      const [x, y] = view.toScreen(p);
      const covers =
        x > box.x - 8 && x < box.x + box.width + 8 && y > box.y - 8 && y < box.y + box.height + 8;
      expect(covers).toBe(false);
    }
    expect(box.height).toBeLessThan(400);
  });

  it('never hides a handle where a smaller size fits a corner: it takes the figure’s small size', () => {
    const { view, painter } = unitSquare();
    // Handles in a cross through the middle: four quarters of about 290 × 190 px are left.
    const handles: [number, number][] = [];
    for (let i = 1; i < 10; i++) handles.push([i / 10, 0.5], [0.5, i / 10]);
    for (const p of handles) painter.handle(p);
    // About 330 characters: 9 lines of 15 px text in a quarter's width are too tall for it, 12 px fit.
    const text = Array.from(
      { length: 6 },
      (_, i) => `Sentence ${i + 1} of a long note, said here in full.`,
    ).join(' ');
    painter.note(text);
    painter.placeLabels();
    const box = painter.labels.find((b) => b.text.startsWith('Sentence'))!;
    const r = painter.theme.sizes.handle;
    for (const p of handles) {
      const [x, y] = view.toScreen(p);
      const covers =
        x > box.x - r && x < box.x + box.width + r && y > box.y - r && y < box.y + box.height + r;
      expect(covers, `the handle at (${x}, ${y})`).toBe(false);
    }
    const sizes = (painter.ctx as SvgContext).elements
      .filter((e) => e.startsWith('<text') && e.includes('Sentence'))
      .map((e) => Number(/font-size="([\d.]+)"/.exec(e)![1]));
    expect(new Set(sizes)).toEqual(new Set([painter.theme.sizes.small]));
  });
  it('hides points or strokes, when it must hide something, before a handle', () => {
    const { view, painter } = unitSquare();
    painter.handle([0.1, 0.9]);
    for (const x of [0.7, 0.8, 0.9]) painter.dot([x, 0.9], '#000', 6);
    painter.polyline(
      [
        [0.6, 0.85],
        [1, 0.85],
      ],
      { width: 3 },
    );
    const [hx, hy] = view.toScreen([0.1, 0.9]);
    const [dx, dy] = view.toScreen([0.8, 0.9]);
    const around = (x: number, y: number) => ({ x: x - 40, y: y - 20, width: 80, height: 40 });
    // The handle's box first: the one with three points and a stroke is chosen.
    expect(leastHidden(painter, [around(hx, hy), around(dx, dy)])).toBe(1);
  });
  it('says it briefly where the whole note would hide a handle in a small figure', () => {
    const view = new Viewport(340, 150);
    view.resize(340, 150);
    view.fit({ minX: 0, minY: 0, maxX: 1, maxY: 1 }, 0);
    const painter = new Painter(new SvgContext(), view, makeTheme(false, false));
    painter.holdLabels();
    // Handles down the middle and across the top and the foot: free are two
    // strips between them, about 155 × 90 px, at the middle of each side.
    const handles: [number, number][] = [0.15, 0.3, 0.45, 0.6, 0.75, 0.9].flatMap((t) => [
      [0.5, t] as [number, number],
      [t, 0.15] as [number, number],
      [t, 0.85] as [number, number],
    ]);
    for (const p of handles) painter.handle(p);
    const brief = 'Cusp: T, N and κ undefined';
    painter.note(
      'Cusp: P′(t) = 0, the curve stops and turns back. T = P′/|P′| divides by 0: T, N, κ and the osculating circle are undefined.',
      { brief },
    );
    painter.placeLabels();
    const box = painter.labels.at(-1)!;
    expect(box.text).toBe(brief);
    for (const p of handles) {
      const [x, y] = view.toScreen(p);
      const r = painter.theme.sizes.handle;
      const covers =
        x > box.x - r && x < box.x + box.width + r && y > box.y - r && y < box.y + box.height + r;
      expect(covers, `the handle at (${x}, ${y})`).toBe(false);
    }
  });
});

describe('a figure’s note, in the page’s notation', () => {
  it('names points with subscripts, as the same note in the panel does', () => {
    // Road's "Villages on top of each other (P2 = P3)" read P₂ = P₃ in the
    // panel and "P2 = P3" on the map.
    const { painter } = unitSquare();
    painter.note('Villages on top of each other (P2 = P3): the road may turn sharply at D2.');
    painter.placeLabels();
    const svg = painter.ctx as SvgContext;
    const words = svg.texts.join(' ');
    expect(words).toContain('P₂ = P₃');
    expect(words).toContain('D₂');
    expect(words).not.toMatch(/P2|P3|D2/);
  });
});
