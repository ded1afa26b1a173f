import katex from 'katex';
import { afterEach, describe, expect, it } from 'vitest';
import {
  minusSigns,
  parseLetter,
  renamePlain,
  renameTex,
  say,
  sayTex,
  setNotation,
  DEFAULT_LETTER,
} from './notation';

describe('the parameter letter in plain text', () => {
  it('renames the lone letter and leaves words alone', () => {
    expect(renamePlain('P(t) at t = 0.4, with 1 − t and t₁', 't', 'mu')).toBe(
      'P(μ) at μ = 0.4, with 1 − μ and μ₁',
    );
    // "t" inside words, after an apostrophe, and the tangent T are not the parameter.
    expect(renamePlain('it doesn’t start at the tangent T', 't', 'mu')).toBe(
      'it doesn’t start at the tangent T',
    );
    expect(renamePlain("don't stop at t", 't', 'u')).toBe("don't stop at u");
    // A subscript letter is the node's index: tₖ is a value of the parameter.
    expect(renamePlain('Lₖ(t) is 1 at tₖ, not at tᵢ', 't', 'mu')).toBe(
      'Lₖ(μ) is 1 at μₖ, not at μᵢ',
    );
  });

  it('renames μ wherever it is, and nothing when the letters agree', () => {
    expect(renamePlain('W(N, i, μ) at μ₁ = 0.2', 'mu', 't')).toBe('W(N, i, t) at t₁ = 0.2');
    expect(renamePlain('W(N, i, μ)', 'mu', 'mu')).toBe('W(N, i, μ)');
    // u is renamed alone, never in "curve" or "u₀"'s neighbours' words.
    expect(renamePlain('a curve in u, at u₀', 'u', 't')).toBe('a curve in t, at t₀');
  });
});

describe('the parameter letter in TeX', () => {
  it('renames t in maths, not in command names, environment names or data slots', () => {
    const tex = String.raw`\begin{pmatrix}t^3 & t\end{pmatrix}\tfrac{dP}{dt} = \left(1-t\right)\htmlData{slot=t}{x}`;
    expect(renameTex(tex, 't', 'u')).toBe(
      String.raw`\begin{pmatrix}u^3 & u\end{pmatrix}\tfrac{dP}{du} = \left(1-u\right)\htmlData{slot=t}{x}`,
    );
  });

  it('renames words in \\text as plain text', () => {
    expect(renameTex(String.raw`\text{at }t\text{ = 0.4, the tangent}`, 't', 'mu')).toBe(
      String.raw`\text{at }{\mu}\text{ = 0.4, the tangent}`,
    );
  });

  it('renames \\mu and a typed μ, and keeps \\mu’s neighbours apart', () => {
    expect(renameTex(String.raw`P(\mu)=\mu^2 \mu_1 μ`, 'mu', 't')).toBe('P(t)=t^2 t_1 t');
    // {\mu} never runs into the letter after it ("\mux").
    expect(renameTex('tx', 't', 'mu')).toBe(String.raw`{\mu}x`);
  });

  it('gives TeX that KaTeX typesets, for every pair of letters', () => {
    const texts = [
      String.raw`P(t) = \sum_{i=0}^{3} W(3, i, t)\,P_i,\quad \frac{d}{dt}(1-t)^3`,
      String.raw`\begin{aligned}P(\mu) &= U M \mathbf{P}\end{aligned}`,
    ];
    for (const tex of texts)
      for (const from of ['t', 'mu'] as const)
        for (const to of ['t', 'mu', 'u'] as const)
          expect(() =>
            katex.renderToString(renameTex(tex, from, to), { throwOnError: true }),
          ).not.toThrow();
  });
});

describe('the page’s letters', () => {
  afterEach(() => setNotation(null, DEFAULT_LETTER));

  it('says a lesson’s text in the reader’s letter, and leaves a lesson of its own letters alone', () => {
    setNotation('mu', 'u');
    expect(say('P(μ)')).toBe('P(u)');
    expect(sayTex(String.raw`P(\mu)`)).toBe('P(u)');
    setNotation(null, 'u');
    expect(say('x(u, v) at t')).toBe('x(u, v) at t');
  });

  it('reads a link’s letter', () => {
    expect(parseLetter('mu')).toBe('mu');
    expect(parseLetter('μ')).toBe('mu');
    expect(parseLetter('t')).toBe('t');
    expect(parseLetter('x')).toBeNull();
  });
});

describe('a negative number reads with a minus sign', () => {
  it('turns the hyphen that starts a number into U+2212', () => {
    expect(minusSigns('-0.65')).toBe('\u22120.65');
    expect(minusSigns('(6.2920, -0.1907)')).toBe('(6.2920, \u22120.1907)');
    expect(minusSigns('κ(0.3) = -1.1144')).toBe('κ(0.3) = \u22121.1144');
    expect(minusSigns('-3.3943 | -3.3943')).toBe('\u22123.3943 | \u22123.3943');
    expect(minusSigns('from -.5 to [-2, 3]')).toBe('from \u2212.5 to [\u22122, 3]');
  });

  it('leaves a hyphen between words, digits or after a bracket, and text that has none', () => {
    for (const text of [
      'P0-P1',
      'steps 2-4',
      'x-1',
      'well-known',
      '1e-9',
      '(a)-1',
      'a - 3',
      '−0.5',
      'C²',
    ])
      expect(minusSigns(text)).toBe(text);
  });
});
