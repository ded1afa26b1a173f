import { describe, expect, it } from 'vitest';
import { Painter } from '../../render/painter';
import { SvgContext } from '../../render/svgContext';
import { makePaperTheme, makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';
import { layoutFrame } from './frameLayout';

const specs = [{ id: 'curve', weight: 1.5 }, { id: 'basis' }, { id: 'knots', height: 64 }];
const box = { x: 0, y: 0, w: 600, h: 300 };
const round = (b: { x: number; y: number; w: number; h: number }) =>
  [b.x, b.y, b.w, b.h].map((v) => Math.round(v * 100) / 100);

describe('a frame’s figures on paper', () => {
  it('splits a row by its weights and keeps a strip’s height in a column', () => {
    const layout = { row: ['curve', { column: ['basis', 'knots'] }], weights: [2, 1] };
    const placed = layoutFrame(layout, specs, new Set(['curve', 'basis', 'knots']), box);
    // By hand: 600 × 2/3 = 400 for the curve; the column (200 wide) gives the
    // knot strip min(64, 22 % of 300 = 66) = 64 and the basis the other 236.
    expect(placed.figures.map((f) => [f.id, ...round(f.box)])).toEqual([
      ['curve', 0, 0, 400, 300],
      ['basis', 400, 0, 200, 236],
      ['knots', 400, 236, 200, 64],
    ]);
  });

  it('closes the box of a figure the step hides', () => {
    const layout = { row: ['curve', { column: ['basis', 'knots'] }], weights: [2, 1] };
    const placed = layoutFrame(layout, specs, new Set(['curve']), box);
    expect(placed.figures.map((f) => [f.id, ...round(f.box)])).toEqual([['curve', 0, 0, 600, 300]]);
  });

  it('stacks a row whose figures would be far taller than wide', () => {
    // Two figures side by side in 300 × 400 would be 150 wide and 400 tall each.
    const placed = layoutFrame('row', specs.slice(0, 2), new Set(['curve', 'basis']), {
      x: 0,
      y: 0,
      w: 300,
      h: 400,
    });
    // Stacked by their weights 1.5 : 1: 240 and 160 tall.
    expect(placed.figures.map((f) => [f.id, ...round(f.box)])).toEqual([
      ['curve', 0, 0, 300, 240],
      ['basis', 0, 240, 300, 160],
    ]);
  });

  it('gives a grid its headings and equal cells, without rows it does not show', () => {
    const grid = {
      grid: {
        columns: ['C⁰', 'C¹'],
        rows: ['A', 'B'],
        cells: [
          ['a0', 'a1'],
          ['b0', 'b1'],
        ],
      },
    };
    const ids = ['a0', 'a1', 'b0', 'b1'].map((id) => ({ id }));
    const placed = layoutFrame(grid, ids, new Set(['a0', 'a1']), { x: 0, y: 0, w: 464, h: 222 });
    // One row shown: 200 × 200 cells after a 64 px heading column and a 22 px heading row.
    expect(placed.figures.map((f) => [f.id, ...round(f.box)])).toEqual([
      ['a0', 64, 22, 200, 200],
      ['a1', 264, 22, 200, 200],
    ]);
    expect(placed.headings.map((h) => h.text)).toEqual(['C⁰', 'C¹', 'A']);
  });
});

describe('paper', () => {
  const stroke = (theme: ReturnType<typeof makeTheme>, colour: string) => {
    const svg = new SvgContext();
    const painter = new Painter(svg, new Viewport(100, 100), theme);
    painter.segment([0, 0], [1, 1], { color: colour });
    return svg.elements.join('');
  };

  it('tells series apart by dash as well as colour, but not the curve or the accent', () => {
    const paper = makePaperTheme();
    const dashed = paper.palette.filter((c) => /stroke-dasharray/.test(stroke(paper, c)));
    // Six of the eight series colours carry a dash; slot 0 and the accent stay solid.
    expect(dashed).toHaveLength(6);
    expect(stroke(paper, paper.accent)).not.toMatch(/stroke-dasharray/);
    expect(stroke(paper, paper.curve)).not.toMatch(/stroke-dasharray/);
    // Each dashed series has a pattern of its own.
    const patterns = dashed.map((c) => /stroke-dasharray="([^"]+)"/.exec(stroke(paper, c))![1]);
    expect(new Set(patterns).size).toBe(6);
    // On screen nothing changes.
    const screen = makeTheme(false, false);
    for (const c of screen.palette) expect(stroke(screen, c)).not.toMatch(/stroke-dasharray/);
  });
});
