import { describe, expect, it } from 'vitest';
import { labelEvery, ticks } from './axes';

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
