import { describe, expect, it } from 'vitest';
import { weightText } from './tex';

describe('a weight in words, for the weights table', () => {
  it('writes W(N, i, μ) worked out as the notes write it, powers raised', () => {
    // By hand: W(3, 1, 0.3) = C(3, 1)·0.3·0.7², W(3, 0, 0.5) = 1·0.5³, W(3, 3, 0.5) = 1·0.5³.
    expect(weightText(3, 1, 0.3)).toBe('W(3, 1, 0.3) = 3 · 0.3 · 0.7²');
    expect(weightText(3, 0, 0.5)).toBe('W(3, 0, 0.5) = 1 · 0.5³');
    expect(weightText(3, 3, 0.5)).toBe('W(3, 3, 0.5) = 1 · 0.5³');
    // C(10, 4) = 210; 1 − 0.25 = 0.75 to the sixth.
    expect(weightText(10, 4, 0.25)).toBe('W(10, 4, 0.25) = 210 · 0.25⁴ · 0.75⁶');
    // C(12, 11) = 12: a two-digit power.
    expect(weightText(12, 1, 0.1)).toBe('W(12, 1, 0.1) = 12 · 0.1 · 0.9¹¹');
  });

  it('writes 1 − μ without a rounding residue, and the ends as 0 and 1', () => {
    // 1 − 0.7 = 0.30000000000000004 in floating point.
    expect(weightText(2, 1, 0.7)).toBe('W(2, 1, 0.7) = 2 · 0.7 · 0.3');
    expect(weightText(2, 0, 0)).toBe('W(2, 0, 0) = 1 · 1²');
    expect(weightText(2, 2, 1)).toBe('W(2, 2, 1) = 1 · 1²');
    expect(weightText(1, 0, 1)).toBe('W(1, 0, 1) = 1 · 0');
  });
});
