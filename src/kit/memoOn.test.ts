import { describe, expect, it } from 'vitest';
import { memoLast, memoOn, sameValues } from './memoOn';

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

describe('memoLast', () => {
  it('computes again only when an argument (or the key given) differs from the last call', () => {
    let runs = 0;
    const area = memoLast((w: number, h: number) => {
      runs++;
      return w * h;
    });
    expect(area(2, 3)).toBe(6);
    expect(area(2, 3)).toBe(6);
    expect(runs).toBe(1);
    expect(area(3, 2)).toBe(6);
    expect(runs).toBe(2);
    // NaN is the same as NaN, and 0 is not −0 (Object.is): a value, not a comparison.
    expect(area(NaN, 1)).toBeNaN();
    expect(area(NaN, 1)).toBeNaN();
    expect(runs).toBe(3);
    expect(area(-0, 1)).toBe(-0);
    expect(runs).toBe(4);
    // An explicit key: the same key keeps the answer, whatever the arguments.
    expect(area.keyed(['k'], 4, 4)).toBe(16);
    expect(area.keyed(['k'], 5, 5)).toBe(16);
    expect(area.keyed(['k', 1], 5, 5)).toBe(25);
    expect(runs).toBe(6);
  });

  it('sameValues compares lists item by item, and by length', () => {
    const p = [1, 2];
    expect(sameValues([p, 1, 'a'], [p, 1, 'a'])).toBe(true);
    expect(sameValues([[1, 2]], [[1, 2]])).toBe(false);
    expect(sameValues([1, 2], [1, 2, 3])).toBe(false);
    expect(sameValues([], [])).toBe(true);
  });
});
