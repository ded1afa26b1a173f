import { describe, expect, it } from 'vitest';
import { liveParts } from './liveParts';

describe('the step formula as live parts', () => {
  it('decimals become slots; indices, integers and exponents of 10 stay in the shape', () => {
    expect(
      liveParts('C(0.300) = \\dfrac{4.00\\cdot0.588\\,x_{2}}{2.764} = (3.06,\\ -3.64)'),
    ).toEqual({
      shape: 'C(\\val) = \\dfrac{\\val\\cdot\\val\\,x_{2}}{\\val} = (\\val,\\ \\val)',
      values: ['0.300', '4.00', '0.588', '2.764', '3.06', '-3.64'],
    });
    expect(liveParts('Q_{4}(0) = \\tfrac16(x_{1} + 4x_{2} + x_{3}) = 1.2e-16')).toEqual({
      shape: 'Q_{4}(0) = \\tfrac16(x_{1} + 4x_{2} + x_{3}) = \\val',
      values: ['1.2e-16'],
    });
  });
});
