import { describe, expect, it } from 'vitest';
import { keepShown, parseTriple } from './netTable';

describe('a cell of the control net, typed', () => {
  it('reads three numbers, with commas, semicolons or spaces, and a true minus', () => {
    expect(parseTriple('2, 1, −1.25')).toEqual([2, 1, -1.25]);
    expect(parseTriple('2; 1 -1.25')).toEqual([2, 1, -1.25]);
    expect(parseTriple('2, oops')).toBeNull();
  });

  it('keeps the exact value of a coordinate left as the cell showed it', () => {
    // A dragged point: the cell showed "0.043, 1, 0.065"; z was typed anew.
    const was = [0.04266809466, 1, 0.06483287852];
    const text = '0.043, 1, 0.5';
    expect(keepShown(parseTriple(text)!, text, was)).toEqual([0.04266809466, 1, 0.5]);
    // Typed over with what it rounds to, written otherwise: the typed value.
    const typed = '0.0430, 1, 0.065';
    expect(keepShown(parseTriple(typed)!, typed, was)).toEqual([0.043, 1, 0.06483287852]);
  });
});
