import katex from 'katex';
import { describe, expect, it } from 'vitest';
import {
  continuityName,
  smallNumber,
  superscript,
  filled,
  fixed,
  sub,
  subscriptNames,
  texResidue,
  texPoint,
  termRow,
  texT,
  texTogether,
  together,
  pointWords,
  trimmed,
  words,
} from './format';

// Exact texts: captions and formulas are compared with reviewed screenshots.
describe('format', () => {
  it('writes indices as Unicode subscripts', () => {
    expect([0, 3, 12, 109].map(sub)).toEqual(['₀', '₃', '₁₂', '₁₀₉']);
  });

  it('trims numbers to their digits, never "-0"', () => {
    expect([0.5, 0.125, 0.1236, -0.0001, 2].map((v) => trimmed(v, 3))).toEqual([
      '0.5',
      '0.125',
      '0.124',
      '0',
      '2',
    ]);
    expect([-2.3456, -0.0004, 1 / 3].map(words)).toEqual(['−2.346', '0', '0.333']);
    expect([0.3, 1 / 3, 1 - 0.7].map(texT)).toEqual(['0.3', '0.3333', '0.3']);
  });

  it('writes TeX points, tiny numbers and filled live formulas', () => {
    expect(texPoint([1, -0.0001], 3)).toBe('(1.000,\\ 0.000)');
    // A rounding residue reads 0 (#19); a true difference keeps four decimals.
    expect(texResidue(8.9e-16)).toBe('0');
    expect(texResidue(-2.69e-16)).toBe('0');
    expect(texResidue(0)).toBe('0');
    expect(texResidue(0.00125)).toBe('0.0013');
    expect(filled({ shape: 'x = \\val + \\val', values: ['1.00', '2.50'] })).toBe(
      'x = 1.00 + 2.50',
    );
  });
});

describe('together', () => {
  it('writes exact coordinates as worked by hand, and rounded ones all to the same digits', () => {
    // Exact: P(0.1) of the arch is (0.243 + 0.081 + 0.004, 0.486 + 0.054) = (0.328, 0.54).
    expect(texTogether([0.243 + 0.081 + 0.004, 0.486 + 0.054], 4)).toBe('(0.328,\\ 0.54)');
    expect(pointWords([42, 21.5])).toBe('(42, 21.5)');
    // One coordinate rounded: the others say their precision (#19: "(−1.962, 2.569, 9)").
    expect(pointWords([-1.96204, 2.5691, 9])).toBe('(−1.962, 2.569, 9.000)');
    expect(pointWords([1 / 3, 1])).toBe('(0.333, 1.000)');
    expect(together([0.75, 0.75, 1.125], 4)).toEqual(['0.75', '0.75', '1.125']);
    expect(together([0.7313, 1 / 7], 4)).toEqual(['0.7313', '0.1429']);
    // No negative zero, either way.
    expect(pointWords([-0.00001, 2])).toBe('(0.000, 2.000)');
    expect(pointWords([-0, 2])).toBe('(0, 2)');
  });
});

describe('fixed', () => {
  it('writes fixed decimals with a true minus and no negative zero', () => {
    expect(fixed(-1.5, 2)).toBe('−1.50');
    expect(fixed(-0.00001, 4)).toBe('0.0000');
    expect(fixed(2, 3)).toBe('2.000');
  });
});

describe('subscriptNames', () => {
  it('writes the index of a point, gradient or weight as a subscript, and nothing else', () => {
    expect(subscriptNames('The 5 points P0 … P4 to pass through')).toBe(
      'The 5 points P₀ … P₄ to pass through',
    );
    expect(subscriptNames('H0P1 + H1P2 + H2D1 + H3D2')).toBe('H₀P₁ + H₁P₂ + H₂D₁ + H₃D₂');
    expect(subscriptNames('P10 and Q4, L0(t) = 1, B3')).toBe('P₁₀ and Q₄, L₀(t) = 1, B₃');
    // Continuity, a number, a word and a name already written stay as they are.
    expect(subscriptNames('C1 and G1 at 1.5, MP3 player, P₂')).toBe(
      'C1 and G1 at 1.5, MP3 player, P₂',
    );
    expect(subscriptNames('at P1.5 of the way')).toBe('at P1.5 of the way');
    // Two indices, as a net's points and de Casteljau's levels have them.
    expect(subscriptNames('P2,1: type three numbers; P1,0 and P10,12')).toBe(
      'P₂,₁: type three numbers; P₁,₀ and P₁₀,₁₂',
    );
    // Letters for indices, alone or in brackets as code writes them.
    expect(subscriptNames('P0 … Pm and D0 … Dm; each Di')).toBe('P₀ … Pₘ and D₀ … Dₘ; each Dᵢ');
    expect(subscriptNames('(P(i−1) + 4Pi + P(i+1))/6')).toBe('(Pᵢ₋₁ + 4Pᵢ + Pᵢ₊₁)/6');
    expect(subscriptNames('u = u(p) + t·(u(m+1) − u(p)), x(p̄)')).toBe(
      'u = uₚ + t·(uₘ₊₁ − uₚ), x(p̄)',
    );
    expect(subscriptNames('each N(i,1) blends N(i,0) and N(i+1,0) on [u(i), u(i+1))')).toBe(
      'each Nᵢ,₁ blends Nᵢ,₀ and Nᵢ₊₁,₀ on [uᵢ, uᵢ₊₁)',
    );
    // A point of the curve, a value at a number, and words stay as they are.
    expect(subscriptNames('P(t), P(0), N(u), Pixels, Ping, Dmitri, a Pi(')).toBe(
      'P(t), P(0), N(u), Pixels, Ping, Dmitri, a Pi(',
    );
  });
});

describe('smallNumber', () => {
  // Written by hand, as a lecturer writes them: never "3.7e-15".
  it('writes a power of ten with superscript digits and true minus signs', () => {
    expect(smallNumber(3.7e-15)).toBe('3.7 × 10⁻¹⁵');
    expect(smallNumber(-2.04e-6)).toBe('−2.0 × 10⁻⁶');
    expect(smallNumber(0)).toBe('0');
    expect(smallNumber(1.25e3)).toBe('1.3 × 10³');
  });
  it('superscript writes any whole number', () => {
    expect(superscript(2)).toBe('²');
    expect(superscript(-10)).toBe('⁻¹⁰');
  });

  it('continuityName raises the order, as the notes write C¹ and G²', () => {
    expect(continuityName('C0')).toBe('C⁰');
    expect(continuityName('C1')).toBe('C¹');
    expect(continuityName('G2')).toBe('G²');
    expect(continuityName('none')).toBe('none');
  });
});

describe('termRow', () => {
  // KaTeX sets a formula as "bases", the pieces a line may break between:
  // one after each top-level = or +, and one at each \allowbreak.
  const bases = (tex: string) =>
    (katex.renderToString(tex, { displayMode: true }).match(/class="base"/g) ?? []).length;

  it('breaks only between its equations, after their commas', () => {
    const terms = ['B_0(0.3) = 0.0572', 'B_1(0.3) = 0.5902', 'B_2(0.3) = 0.3482'];
    expect(termRow(terms)).toBe(
      '{B_0(0.3) = 0.0572},\\allowbreak\\ {B_1(0.3) = 0.5902},\\allowbreak\\ {B_2(0.3) = 0.3482}',
    );
    // Three equations, three pieces; joined plainly, each "=" also starts one.
    expect(bases(termRow(terms))).toBe(3);
    expect(bases(terms.join(',\\ '))).toBeGreaterThan(3);
  });
});
