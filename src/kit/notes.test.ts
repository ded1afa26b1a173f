import { describe, expect, it } from 'vitest';
import { slipText } from './notes';

describe('what a lesson says about the course notes', () => {
  it('says a slip kindly, in a sentence whose verb agrees with the document', () => {
    expect(slipText('lecture', 'K = T′(t)', 'K is dT/ds.')).toBe(
      'The lecture notes write K = T′(t). K is dT/ds.',
    );
    expect(slipText('slides', 'x₀ = xₘ', 'Three points wrap.')).toBe(
      'The lecture slides write x₀ = xₘ. Three points wrap.',
    );
    expect(slipText('continuation', 'Lₖ(t)', 'Lₖ(tᵢ) is meant.')).toBe(
      'The continuation notes write Lₖ(t). Lₖ(tᵢ) is meant.',
    );
    expect(slipText('practical', 'd²/dt²', 'The first derivative is d/dt.')).toBe(
      'The practical (TP2) writes d²/dt². The first derivative is d/dt.',
    );
  });
});
