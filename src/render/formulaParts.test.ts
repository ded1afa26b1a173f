import { describe, expect, it } from 'vitest';
import { SLOT } from './formula';
import { slotNumbers } from './formulaParts';

describe('slotNumbers', () => {
  it('makes each decimal number a slot and keeps signs, integers and TeX lengths in the shape', () => {
    const parts = slotNumbers(
      'P_{12}(0.25) = (-1.50,\\ 3.00)\\kern0.5em + 2\\hspace{1.5 em} x^{2}',
    );
    expect(parts.values).toEqual(['0.25', '1.50', '3.00']);
    expect(parts.shape).toBe(
      `P_{12}(${SLOT}) = (-${SLOT},\\ ${SLOT})\\kern0.5em + 2\\hspace{1.5 em} x^{2}`,
    );
  });

  it('takes a number right after a command, and an exponent with its number', () => {
    expect(
      slotNumbers('C(0.300) = \\dfrac{4.00\\cdot0.588\\,x_{2}}{2.764} = (3.06,\\ -3.64)'),
    ).toEqual({
      shape: `C(${SLOT}) = \\dfrac{${SLOT}\\cdot${SLOT}\\,x_{2}}{${SLOT}} = (${SLOT},\\ -${SLOT})`,
      values: ['0.300', '4.00', '0.588', '2.764', '3.06', '3.64'],
    });
    expect(slotNumbers('Q_{4}(0) = \\tfrac16(x_{1} + 4x_{2}) = 1.2e-16').values).toEqual([
      '1.2e-16',
    ]);
  });

  it('fills back to the same TeX', () => {
    const texts = [
      '\\frac{1}{6}\\begin{pmatrix}1.000 & -4.25\\end{pmatrix}',
      'no numbers',
      '1.5e+3',
    ];
    for (const text of texts) {
      const { shape, values } = slotNumbers(text);
      expect(shape.split(SLOT).reduce((acc, part, i) => acc + values[i - 1] + part)).toBe(text);
    }
  });
});
