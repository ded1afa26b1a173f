import { describe, expect, it } from 'vitest';
import { memoOn } from './memoOn';

describe('memoOn', () => {
  it('computes again only when a field it reads changes', () => {
    let runs = 0;
    const sum = memoOn<{ p: number[]; t: number; step: number }, 'p' | 't', number>(
      ['p', 't'],
      ({ p, t }) => {
        runs++;
        return p.reduce((a, b) => a + b, 0) * t;
      },
    );
    const s = { p: [1, 2, 3], t: 2, step: 0 };
    expect(sum(s)).toBe(12);
    // Another step, the same points and t: no new work.
    expect(sum({ ...s, step: 3 })).toBe(12);
    expect(runs).toBe(1);
    expect(sum({ ...s, t: 1 })).toBe(6);
    // New points, even with the same numbers, are a new input (states are never mutated).
    expect(sum({ ...s, t: 1, p: [1, 2, 3] })).toBe(6);
    expect(runs).toBe(3);
  });
});
