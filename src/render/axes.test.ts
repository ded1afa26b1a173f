import { describe, expect, it } from 'vitest';
import { labelEvery, ticks } from './axes';
import type { LabelBox } from './labels';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/** How far `label` stands from each tick number in its row (px; negative where they overlap). */
function gapsToNumbers(painter: Painter, label: LabelBox): { number: string; apart: number }[] {
  return painter.labels
    .filter((b) => /^−?\d/.test(b.text) && Math.abs(b.y - label.y) < b.height / 2)
    .map((b) => ({
      number: b.text,
      apart: Math.max(b.x - (label.x + label.width), label.x - (b.x + b.width)),
    }));
}

describe('labelled ticks on a short plot', () => {
  it('labels every tick when they are far enough apart, else every 2nd, 4th, 5th, 10th …', () => {
    // Ticks 0.25 apart on a plot 1.25 units tall: 120 px tall → 24 px apart, labels need 20.
    expect(labelEvery(24, 20)).toBe(1);
    // 60 px tall → 12 px apart: every second tick (24 px).
    expect(labelEvery(12, 20)).toBe(2);
    expect(labelEvery(6, 20)).toBe(4);
    expect(labelEvery(4.5, 20)).toBe(5);
    expect(labelEvery(2, 20)).toBe(10);
    expect(labelEvery(0, 20)).toBe(1);
  });
  it('the labelled ticks are whole multiples of k steps, so 0 keeps its label', () => {
    const k = labelEvery(12, 20);
    const labelled = ticks(-0.5, 1, 0.25).filter((y) => Math.round(y / 0.25) % k === 0);
    expect(labelled).toEqual([-0.5, 0, 0.5, 1]);
  });
});

describe('the x-axis name', () => {
  it('never stands beside a tick number as if part of it (u and 10 read “u10”), at any width', () => {
    // b-splines' basis plot at a laptop's 320 px read "0 2 4 6 8 u10".
    for (const projector of [false, true])
      for (let width = 160; width <= 1000; width += 20) {
        const view = new Viewport();
        view.resize(width, 400);
        const bounds = { minX: -1, maxX: 10, minY: -0.1, maxY: 1.1 };
        view.fit(bounds, [40, 30], false);
        const painter = new Painter(new SvgContext(), view, makeTheme(false, projector));
        painter.plotAxes(bounds, 1, 0.25, 'u', '');
        const name = painter.labels.find((b) => b.text === 'u')!;
        expect(name, `${width} px`).toBeDefined();
        const small = painter.theme.sizes.small;
        for (const { number, apart } of gapsToNumbers(painter, name))
          expect(
            apart,
            `${width} px: “u” ${apart.toFixed(1)} px from “${number}”`,
          ).toBeGreaterThanOrEqual(small / 2);
      }
  });
});

describe('a plot’s axes and tick numbers, to the labels written on the plot', () => {
  // Curvature's κ plot: "C²" at a join was set on the zero line (a struck-out
  // C) and against the tick number "2" ("2C²"): the axes were not in the ink
  // and a label could touch another.
  const bounds = { minX: 0, maxX: 4, minY: -1.2, maxY: 3.2 };
  const plot = (projector: boolean) => {
    const view = new Viewport();
    view.resize(900, 300);
    view.fit(bounds, [40, 30], false);
    const painter = new Painter(new SvgContext(), view, makeTheme(false, projector));
    painter.plotAxes(bounds, 0.5, 1, 't', '');
    return painter;
  };
  for (const projector of [false, true]) {
    const mode = projector ? 'presenter' : 'normal';
    it(`a label asked for on the zero line is moved off it (${mode})`, () => {
      const painter = plot(projector);
      const [, axisY] = painter.view.toScreen([0, 0]);
      painter.label('C²', [2, 0], { dx: 4, dy: 0, halo: true });
      const label = painter.labels.find((b) => b.text === 'C²')!;
      expect(label).toBeDefined();
      const crossed = label.y < axisY && label.y + label.height > axisY;
      expect(
        crossed,
        `“C²” spans ${label.y.toFixed(1)}–${(label.y + label.height).toFixed(1)}, axis at ${axisY.toFixed(1)}`,
      ).toBe(false);
    });
    it(`a label asked for beside a tick number keeps a gap from it (${mode})`, () => {
      const painter = plot(projector);
      const small = painter.theme.sizes.small;
      // In the row of the tick numbers, just right of "2".
      painter.label('C²', [2, bounds.minY], { dx: small * 0.4, dy: small * 0.9, halo: true });
      const label = painter.labels.find((b) => b.text === 'C²')!;
      expect(label).toBeDefined();
      for (const { number, apart } of gapsToNumbers(painter, label))
        expect(apart, `“C²” ${apart.toFixed(1)} px from “${number}”`).toBeGreaterThanOrEqual(
          small * 0.25,
        );
    });
  }
});
