import { describe, expect, it } from 'vitest';
import { boxesNumber } from './cellBoxes';
import { fitsBox, grownWidth, sameWidth } from './liveBoxes';

describe('when a live number keeps its box', () => {
  it('keeps it when only digits change, frees it for a digit more or a sign', () => {
    expect(sameWidth('1.25', '1.37')).toBe(true);
    expect(sameWidth('0.000', '9.999')).toBe(true);
    expect(sameWidth('9.99', '10.00')).toBe(false);
    expect(sameWidth('0.500', '−0.500')).toBe(false);
    expect(sameWidth('0', '0.002')).toBe(false);
    expect(sameWidth('', '0.000')).toBe(false);
  });
});

describe('when a number mid-drag still fits the box it was measured at', () => {
  it('fits a number no wider, in KaTeX glyphs and in characters', () => {
    // Widths by hand: digits 0.5 em, a point 0.278, a minus sign 0.778.
    expect(fitsBox('0', '−0.014')).toBe(true); // 0.5 ≤ 3.056 em, 1 ≤ 6 characters
    expect(fitsBox('1.02', '−0.014')).toBe(true); // 1.778 ≤ 3.056
    expect(fitsBox('9.99', '1.25')).toBe(true); // only digits differ
    expect(fitsBox('10.0', '−1.5')).toBe(true); // 1.778 ≤ 2.056 em, 4 ≤ 4 characters
  });
  it('does not fit a wider number, a longer one, or words', () => {
    expect(fitsBox('−0.014', '0')).toBe(false);
    expect(fitsBox('12.5', '1.5')).toBe(false); // a digit more
    expect(fitsBox('1.25', '−10')).toBe(false); // as wide in KaTeX (1.778), a character longer in a table
    expect(fitsBox('P1 is an end point', '0.5000')).toBe(false);
    expect(fitsBox('0.5', 'none')).toBe(false);
  });
});

describe('the box of a number that grows mid-drag', () => {
  it('is scaled by glyphs or by characters, whichever grew more', () => {
    // '0' → '0.25': glyphs 0.5 → 1.778 em (×3.556), characters 1 → 4 (×4).
    expect(grownWidth(0.55, '0.25', '0')).toBeCloseTo(2.2, 10);
    // '1.5' → '−1.5': glyphs 1.278 → 2.056 (×1.609), characters 3 → 4 (×1.333).
    expect(grownWidth(1, '−1.5', '1.5')).toBeCloseTo(2.056 / 1.278, 10);
  });
  it('is not estimated for words', () => {
    expect(grownWidth(1, 'none', '0')).toBeUndefined();
    expect(grownWidth(1, '0.5', '')).toBeUndefined();
  });
});

describe('which table cells get a box of their own', () => {
  it('boxes a lone number, not words that may wrap', () => {
    for (const text of ['0', '−0.125', '-3', '1,5', '12.000001'])
      expect(boxesNumber(text)).toBe(true);
    for (const text of ['Σ fₘ fₙ Pₘ,ₙ', '(1, 2)', 'P₀', '', 'x 1', '0.5 1'])
      expect(boxesNumber(text)).toBe(false);
  });
});
