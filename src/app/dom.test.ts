import { describe, expect, it } from 'vitest';
import { splitNumbers } from './dom';

describe('the numbers of a live text', () => {
  it('takes each number with its sign and decimals, and leaves names and words', () => {
    expect(splitNumbers('Weights at μ = 0.57 (N = 3)')).toEqual({
      words: ['Weights at μ = ', ' (N = ', ')'],
      numbers: ['0.57', '3'],
    });
    expect(splitNumbers('(−0.01, 0.13)')).toEqual({
      words: ['(', ', ', ')'],
      numbers: ['−0.01', '0.13'],
    });
    // The 0 of P0, of x₀ and of P′(0)'s prime is part of a name; 6.190 is a number.
    expect(splitNumbers('P0 and x₀1 at |P′(0)| = 6.190')).toEqual({
      words: ['P0 and x₀1 at |P′(', ')| = ', ''],
      numbers: ['0', '6.190'],
    });
  });
  it('keeps the words when only the numbers change', () => {
    const a = splitNumbers('Degree 4, at t = 0.470');
    const b = splitNumbers('Degree 4, at t = 0.5');
    expect(a.words).toEqual(b.words);
    expect(b.numbers).toEqual(['4', '0.5']);
  });
  it('has one word more than numbers, and a text with none is all words', () => {
    expect(splitNumbers('no numbers here')).toEqual({ words: ['no numbers here'], numbers: [] });
    expect(splitNumbers('12')).toEqual({ words: ['', ''], numbers: ['12'] });
  });
});
