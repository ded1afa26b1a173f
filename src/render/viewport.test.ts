import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { Viewport, boundsOf, niceStep } from './viewport';

describe('Viewport', () => {
  it('maps lesson coordinates (y up) to pixels (y down)', () => {
    const v = new Viewport(400, 200);
    v.centerX = 1;
    v.centerY = 2;
    v.scaleX = v.scaleY = 50;
    expect(v.toScreen([1, 2])).toEqual([200, 100]);
    expect(v.toScreen([2, 2])).toEqual([250, 100]);
    expect(v.toScreen([1, 3])).toEqual([200, 50]);
    expect(v.toWorld([250, 50])).toEqual([2, 3]);
  });

  it('round-trips world → screen → world', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -1e4, max: 1e4, noNaN: true }),
        fc.double({ min: -1e4, max: 1e4, noNaN: true }),
        fc.double({ min: 0.01, max: 1e4, noNaN: true }),
        (x, y, s) => {
          const v = new Viewport(640, 480);
          v.scaleX = v.scaleY = s;
          v.centerX = 3;
          v.centerY = -7;
          const [wx, wy] = v.toWorld(v.toScreen([x, y]));
          expect(wx).toBeCloseTo(x, 6);
          expect(wy).toBeCloseTo(y, 6);
        },
      ),
    );
  });

  it('fits bounds inside the padding, keeping the aspect ratio', () => {
    const v = new Viewport(600, 400);
    v.fit({ minX: 0, minY: 0, maxX: 4, maxY: 2 }, 50);
    expect(v.scaleX).toBe(v.scaleY);
    expect(v.scaleX).toBe(125); // 500 px across 4 units beats 300 px up 2 units (150)
    expect(v.toScreen([0, 1])).toEqual([50, 200]);
    expect(v.toScreen([4, 1])).toEqual([550, 200]);
  });

  it('stretches a plot when asked', () => {
    const v = new Viewport(600, 400);
    v.fit({ minX: 0, minY: 0, maxX: 1, maxY: 1 }, 0, false);
    expect(v.toScreen([1, 1])).toEqual([600, 0]);
    expect(v.toScreen([0, 0])).toEqual([0, 400]);
  });

  it('widens a unit up to the factor asked in a short box, and keeps squares in a tall one', () => {
    // 600 × 200 box, a 6 × 6 table: 100 px a unit across, 33⅓ up; at most 1.8 × 33⅓ = 60 across.
    const wide = new Viewport(600, 200);
    wide.fit({ minX: 0, minY: 0, maxX: 6, maxY: 6 }, 0, 1.8);
    expect(wide.scaleY).toBeCloseTo(200 / 6, 12);
    expect(wide.scaleX).toBeCloseTo(60, 12);
    // 200 × 600: 33⅓ across, 100 up; never taller than wide, so 33⅓ both ways.
    const tall = new Viewport(200, 600);
    tall.fit({ minX: 0, minY: 0, maxX: 6, maxY: 6 }, 0, 1.8);
    expect(tall.scaleX).toBeCloseTo(200 / 6, 12);
    expect(tall.scaleY).toBeCloseTo(200 / 6, 12);
    // Within the factor the box is filled: 600 × 400 is 100 by 66⅔, 1.5 × as long across.
    const within = new Viewport(600, 400);
    within.fit({ minX: 0, minY: 0, maxX: 6, maxY: 6 }, 0, 1.8);
    expect(within.toScreen([6, 6])).toEqual([600, 0]);
  });

  it('gives a sane zoom for one point or points on a line', () => {
    const v = new Viewport(600, 400);
    v.fit({ minX: 2, minY: 2, maxX: 2, maxY: 2 }, 50);
    expect(Number.isFinite(v.scaleX)).toBe(true);
    expect(v.toScreen([2, 2])).toEqual([300, 200]);
    v.fit(
      boundsOf([
        [0, 1],
        [5, 1],
      ]),
      50,
    );
    expect(v.scaleX).toBe(100);
  });

  it('zooms about the pointer and pans by pixels', () => {
    const v = new Viewport(600, 400);
    v.fit({ minX: 0, minY: 0, maxX: 6, maxY: 4 }, 0);
    const anchor = [150, 100] as const;
    const before = v.toWorld(anchor);
    v.zoomAt(anchor, 2);
    const after = v.toWorld(anchor);
    expect(after[0]).toBeCloseTo(before[0], 12);
    expect(after[1]).toBeCloseTo(before[1], 12);
    const p = v.toScreen([1, 1]);
    v.panBy(10, -20);
    const q = v.toScreen([1, 1]);
    expect(q[0] - p[0]).toBeCloseTo(10, 9);
    expect(q[1] - p[1]).toBeCloseTo(-20, 9);
  });
});

describe('niceStep', () => {
  it('rounds to 1, 2 or 5 times a power of ten', () => {
    expect(niceStep(0.04)).toBe(0.05);
    expect(niceStep(0.13)).toBe(0.1);
    expect(niceStep(0.27)).toBe(0.2);
    expect(niceStep(7)).toBe(5);
    expect(niceStep(8)).toBe(10);
    expect(niceStep(0)).toBe(1);
    expect(niceStep(Number.NaN)).toBe(1);
  });
});
