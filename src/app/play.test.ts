import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { nextPlayedValue } from './play';

describe('nextPlayedValue', () => {
  it('moves on by the amount, and wraps to the start past the end', () => {
    expect(nextPlayedValue(0.25, 0.5, 0, 1)).toBe(0.75);
    expect(nextPlayedValue(0.9, 0.2, 0, 1)).toBe(0);
    expect(nextPlayedValue(1, 0, 0, 1)).toBe(1);
  });

  it('stays at the start when the first frame comes before the press (a negative step)', () => {
    // Seen on #/blending?mu=0: t = −0.00018 reached bernsteinBasis.
    expect(nextPlayedValue(0, -0.00018, 0, 1)).toBe(0);
    expect(nextPlayedValue(-1, -0.00048, -1, 3)).toBe(-1);
  });

  it('never leaves [min, max], whatever the step', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -10, max: 10, noNaN: true }),
        fc.double({ min: 0.001, max: 10, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: -1, max: 1, noNaN: true }),
        (min, span, at, amount) => {
          const max = min + span;
          const v = nextPlayedValue(min + at * span, amount * span, min, max);
          return v >= min && v <= max;
        },
      ),
    );
  });
});
