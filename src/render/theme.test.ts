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
