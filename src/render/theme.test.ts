import { describe, expect, it } from 'vitest';
import { makeTheme } from './theme';

describe('presenter view sizes read from the back of a lecture hall', () => {
  for (const dark of [false, true]) {
    it(`${dark ? 'dark' : 'light'}: strokes ≥ 4 px, handles ≥ 24 px across, text ≥ 28 px`, () => {
      const { sizes } = makeTheme(dark, true);
      for (const stroke of [sizes.curve, sizes.line, sizes.thin])
        expect(stroke).toBeGreaterThanOrEqual(4);
      expect(2 * sizes.handle).toBeGreaterThanOrEqual(24);
      expect(sizes.label).toBeGreaterThanOrEqual(28);
      expect(sizes.small).toBeGreaterThanOrEqual(28);
    });
  }
});

// WCAG 2 relative luminance and contrast ratio, written here from the spec.
const channel = (v: number) => (v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4);
const rgb = (hex: string) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255);
const luminance = (c: number[]) =>
  0.2126 * channel(c[0]) + 0.7152 * channel(c[1]) + 0.0722 * channel(c[2]);
const contrast = (a: number[], b: number[]) => {
  const [hi, lo] = [luminance(a), luminance(b)].sort((x, y) => y - x);
  return (hi + 0.05) / (lo + 0.05);
};
/** `c` over `back` at opacity `alpha`, then washed a third of the way back (a weak projector). */
const seen = (c: number[], back: number[], alpha: number) =>
  c.map((v, i) => (v * alpha + back[i] * (1 - alpha)) * 0.65 + back[i] * 0.35);

describe('faint marks survive a washed-out projector', () => {
  for (const dark of [false, true]) {
    const theme = makeTheme(dark, true);
    const back = rgb(theme.background);
    it(`${dark ? 'dark' : 'light'}: a hull's tint in any series colour stands off the screen`, () => {
      for (const colour of theme.palette)
        expect(contrast(seen(rgb(colour), back, theme.tint), back), colour).toBeGreaterThan(1.3);
    });
    it(`${dark ? 'dark' : 'light'}: the faint curve behind a construction is still seen`, () => {
      expect(contrast(seen(rgb(theme.curveFaint), back, 1), back)).toBeGreaterThan(2.2);
    });
  }
});
