import { describe, expect, it } from 'vitest';
import { labelEvery, ticks } from './axes';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

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
        for (const number of painter.labels.filter((b) => /^−?\d/.test(b.text))) {
          const sameRow = Math.abs(number.y - name.y) < number.height / 2;
          if (!sameRow) continue;
          const apart = Math.max(
            number.x - (name.x + name.width),
            name.x - (number.x + number.width),
          );
          expect(
            apart,
            `${width} px: “u” ${apart.toFixed(1)} px from “${number.text}”`,
          ).toBeGreaterThanOrEqual(small / 2);
        }
      }
  });
});
