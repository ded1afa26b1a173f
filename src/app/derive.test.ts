import { describe, expect, it } from 'vitest';
import { memoize } from './derive';

describe('memoize: a model is derived once per state', () => {
  it('calls derive once for one state object, however often it is asked', () => {
    let calls = 0;
    const model = memoize((s: { t: number }) => {
      calls++;
      return { double: s.t * 2 };
    });
    const state = { t: 0.4 };
    const first = model(state);
    for (let i = 0; i < 10; i++) expect(model(state)).toBe(first);
    expect(calls).toBe(1);
    expect(first.double).toBe(0.8);
  });

  it('derives again for a new state, and finds an older state again without deriving', () => {
    let calls = 0;
    const model = memoize((s: { t: number }) => {
      calls++;
      return [s.t];
    });
    const a = { t: 1 };
    const b = { ...a, t: 2 };
    const ma = model(a);
    const mb = model(b);
    expect(calls).toBe(2);
    // Undo brings back the old state object: its model is still there.
    expect(model(a)).toBe(ma);
    expect(model(b)).toBe(mb);
    expect(calls).toBe(2);
  });

  it('treats an equal but distinct object as a new state (states are never mutated)', () => {
    let calls = 0;
    const model = memoize((s: { t: number }) => ({ t: s.t, n: ++calls }));
    model({ t: 1 });
    model({ t: 1 });
    expect(calls).toBe(2);
  });
});
