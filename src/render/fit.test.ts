import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { chooseFit } from './fit';

// Presenter view: a caption formula's subscripts are 28.35 px at full size
// (30 px × 1.35 × 0.7), so the back row's 28 px floor is the scale 28/28.35,
// and 12 px is 12/28.35.
const presenter = { readable: 28 / 28.35, least: 12 / 28.35 };
// The side panel: its floor is 12 px, both ways.
const panel = { readable: 0.6, least: 0.6 };

describe('chooseFit: the scale and lines of a formula fitted to its box', () => {
  it('keeps what fits at its own size', () => {
    expect(chooseFit({ box: 500, natural: 400, line: 200, ...presenter })).toEqual({
      scale: 1,
      wraps: false,
    });
  });

  it('shrinks what is a little too wide, down to the view’s floor (worked by hand)', () => {
    // 0.98 × 900 / 1000 = 0.882: the panel's floor allows it.
    expect(chooseFit({ box: 900, natural: 1000, line: 400, ...panel })).toEqual({
      scale: 0.882,
      wraps: false,
    });
  });

  it('in presenter view sets a formula 3% too wide on lines at full size, not at 27.6 px', () => {
    // Shrunk to fit, 0.98 × 336 / 346 = 0.952 would set its subscripts at
    // 27.0 px (a sum beside the caption's words came out at 27.6 px).
    const fit = chooseFit({ box: 336, natural: 346, line: 220, ...presenter });
    expect(fit).toEqual({ scale: 1, wraps: true });
  });

  it('on lines, as large as its widest line allows when that is over the floor', () => {
    // Widest line 950 px in 992: 0.98 × 992 / 950 > 1, so at full size.
    expect(chooseFit({ box: 992, natural: 2400, line: 950, ...presenter })).toEqual({
      scale: 1,
      wraps: true,
    });
    // Widest line 1010 px: 0.98 × 992 / 1010 = 0.9625, under the floor (0.988)
    // but over 12 px, and larger than one line's 0.98 × 992 / 2400 = 0.405.
    const under = chooseFit({ box: 992, natural: 2400, line: 1010, ...presenter });
    expect(under.wraps).toBe(true);
    expect(under.scale).toBeCloseTo((0.98 * 992) / 1010, 10);
  });

  it('rather than scroll a formula that cannot break out of sight, shrinks it under the floor, to 12 px', () => {
    // An aligned expansion whose first line is 1168 px, on a 1024 px projector:
    // 0.98 × 992 / 1168 = 0.8323, seen whole.
    const fit = chooseFit({ box: 992, natural: 1168, line: 0, ...presenter });
    expect(fit.wraps).toBe(false);
    expect(fit.scale).toBeCloseTo((0.98 * 992) / 1168, 10);
    // Wider than 12 px allows: 12 px, and it scrolls.
    expect(chooseFit({ box: 300, natural: 1168, line: 0, ...presenter })).toEqual({
      scale: presenter.least,
      wraps: false,
    });
  });

  it('never sets text under the floor while one line or lines at the floor would fit', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 50, max: 2000, noNaN: true }),
        fc.double({ min: 10, max: 6000, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0.3, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (box, natural, lineShare, readable, leastShare) => {
          const least = Math.max(0.5, readable * leastShare);
          const line = natural * lineShare;
          const m = { box, natural, line, readable: Math.max(readable, least), least };
          const { scale, wraps } = chooseFit(m);
          expect(scale).toBeLessThanOrEqual(1);
          expect(scale).toBeGreaterThanOrEqual(least - 1e-12);
          const fitsAtFloor =
            natural * m.readable <= box * 0.98 || (line > 0 && line * m.readable <= box * 0.98);
          if (fitsAtFloor) expect(scale).toBeGreaterThanOrEqual(m.readable - 1e-12);
          // Lines only for what can break; what fits whole is not broken.
          if (wraps) expect(line).toBeGreaterThan(0);
          if (natural <= box + 1) expect({ scale, wraps }).toEqual({ scale: 1, wraps: false });
        },
      ),
    );
  });
});
