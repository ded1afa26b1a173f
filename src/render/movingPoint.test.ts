import { describe, expect, it } from 'vitest';
import { drawHandles } from './handles';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

// At t = 0 the moving point P(t) is P₀, where P₀'s handle is: drawn in the
// figure's turn, before the handles, the handle's white disc covered it.

const theme = makeTheme(false, true);

function figure() {
  const view = new Viewport(600, 400);
  view.resize(600, 400);
  view.fit({ minX: 0, minY: 0, maxX: 4, maxY: 3 }, 40);
  const svg = new SvgContext();
  const painter = new Painter(svg, view, theme);
  painter.holdLabels();
  return { view, painter, svg };
}

const P0 = [0, 0];
const handles = [
  { id: 'p0', label: 'P_0', position: P0 },
  { id: 'p1', label: 'P_1', position: [4, 3] },
];

/** The index in the SVG of the last element filled with the accent, and of the last handle's fill. */
function order(svg: SvgContext) {
  const elements = svg.toSvg(600, 400).split('><');
  return {
    dot: elements.map((e) => e.includes(`fill="${theme.accent}"`)).lastIndexOf(true),
    handle: elements.map((e) => e.includes(`fill="${theme.handleFill}"`)).lastIndexOf(true),
  };
}

describe('the moving point', () => {
  it('is drawn over the handles, though the figure draws it before them', () => {
    const { painter, svg } = figure();
    painter.movingPoint(P0, 1.6);
    drawHandles(painter, handles);
    painter.placeLabels();
    const { dot, handle } = order(svg);
    expect(handle).toBeGreaterThan(0);
    expect(dot).toBeGreaterThan(handle);
    expect(painter.underHandles).toEqual([]);
  });

  it('a large accent dot drawn before a handle on it is reported hidden', () => {
    const { painter, svg, view } = figure();
    painter.dot(P0, theme.accent, theme.sizes.point * 1.6);
    drawHandles(painter, handles);
    painter.placeLabels();
    const { dot, handle } = order(svg);
    expect(dot).toBeLessThan(handle);
    expect(painter.underHandles).toEqual([view.toScreen(P0)]);
  });

  it('a small one (a tick) or one much larger than the handle (seen round it) is not', () => {
    const { painter } = figure();
    painter.dot(P0, theme.accent, theme.sizes.point);
    painter.dot([4, 3], theme.accent, theme.sizes.handle * 2);
    drawHandles(painter, handles);
    expect(painter.underHandles).toEqual([]);
  });

  it('is drawn at once where nothing is held (a script check draws no handles)', () => {
    const view = new Viewport(600, 400);
    view.resize(600, 400);
    const svg = new SvgContext();
    new Painter(svg, view, theme).movingPoint([0, 0]);
    expect(svg.toSvg(600, 400)).toContain(`fill="${theme.accent}"`);
  });
});

describe('a handle’s name beside the moving point', () => {
  // b-splines NURBS at 1366 × 768: P₂'s name went beside the P(u) dot, and read as its name.
  it('goes nearer its own point than the moving point', () => {
    const { painter, view } = figure();
    const own = [2, 1.5];
    const [x, y] = view.toScreen(own);
    const moving = view.toWorld([x + 69, y + 35]);
    // Ink across the places above the point: the name must go to a side or below.
    for (let ly = y - 90; ly <= y - 12; ly += 8)
      painter.polyline([view.toWorld([x - 200, ly]), view.toWorld([x + 200, ly])], { width: 2 });
    painter.movingPoint(moving, 1.6);
    drawHandles(painter, [{ id: 'p2', label: 'P_2', position: own }]);
    painter.placeLabels();
    const [name] = painter.labels;
    // Measured as the placer and the steps test measure a name: its whole box.
    const box = name;
    const to = ([px, py]: readonly number[]) =>
      Math.hypot(
        Math.max(box.x - px, 0, px - box.x - box.width),
        Math.max(box.y - py, 0, py - box.y - box.height),
      );
    expect(to([x, y])).toBeLessThan(to(view.toScreen(moving)));
  });
});
