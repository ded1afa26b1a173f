import { describe, expect, it } from 'vitest';
import { sameWidth } from './liveBoxes';

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
