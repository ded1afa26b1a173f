import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { narrow, repeat, script, step } from './script';

// The de Casteljau construction of degree n: points, polygon, levels 1 … n, curve.
interface S {
  n: number;
}
type M = { label: string };
const construction = script<S, M, 'points' | 'polygon' | 'level' | 'curve'>(
  step('points', ({ state }) => `The ${state.n + 1} control points`),
  step('polygon', 'The control polygon', () => 'P_{0,i} = P_i'),
  repeat(
    'level',
    (s) => s.n,
    ({ index }) => `Level ${index}`,
    ({ index, times }) => (index === times ? `P(t) = P_{${index},0}` : null),
  ),
  step('curve', 'The curve traced', ({ model }) => model.label),
);
const model: M = { label: 'P(t) = \\sum W P_i' };

describe('a script of named steps', () => {
  it('counts one press per step and per repeat: n + 2 for degree n', () => {
    expect(construction.lastStep({ n: 3 })).toBe(5);
    expect(construction.lastStep({ n: 1 })).toBe(3);
    // A repeat of zero presses is no step at all.
    expect(construction.lastStep({ n: 0 })).toBe(2);
  });

  it('says what each press shows, repeated steps with their index', () => {
    const s = { n: 3 };
    const captions = [0, 1, 2, 3, 4, 5].map((k) => construction.caption(s, model, k));
    expect(captions).toEqual([
      'The 4 control points',
      'The control polygon',
      'Level 1',
      'Level 2',
      'Level 3',
      'The curve traced',
    ]);
    expect([0, 1, 2, 3, 4, 5].map((k) => construction.formula(s, model, k))).toEqual([
      null,
      'P_{0,i} = P_i',
      null,
      null,
      'P(t) = P_{3,0}',
      'P(t) = \\sum W P_i',
    ]);
  });

  it('gives a narrow box the narrow layout of a step that has one, and its one formula otherwise', () => {
    const wideAndNarrow = script<S, M, 'sum' | 'point'>(
      narrow(
        step('sum', 'The sum', () => '\\begin{aligned}&a + b & c + d\\end{aligned}'),
        () => 'a + b\\\\ c + d',
      ),
      step('point', 'The point', () => 'P = (1, 2)'),
    );
    const s = { n: 3 };
    expect(wideAndNarrow.formula(s, model, 0)).toBe('\\begin{aligned}&a + b & c + d\\end{aligned}');
    expect(wideAndNarrow.formula(s, model, 0, true)).toBe('a + b\\\\ c + d');
    expect(wideAndNarrow.formula(s, model, 1, true)).toBe('P = (1, 2)');
    expect(wideAndNarrow.caption(s, model, 0)).toBe('The sum');
  });

  it('reveals by name: what was reached stays shown, repeats count up', () => {
    const s = { n: 3 };
    const at2 = construction.shown(s, 3);
    expect(at2.has('points')).toBe(true);
    expect(at2.has('polygon')).toBe(true);
    expect(at2.count('level')).toBe(2);
    expect(at2.has('level', 2)).toBe(true);
    expect(at2.has('level', 3)).toBe(false);
    expect(at2.has('curve')).toBe(false);
    expect(at2.is('level')).toBe(true);
    expect(at2.index).toBe(2);
    expect(at2.last).toBe(false);
    const end = construction.shown(s, 5);
    expect(end.last).toBe(true);
    expect(end.count('level')).toBe(3);
    expect(end.is('curve')).toBe(true);
    // Past the end is the end; before the start is the start.
    expect(construction.shown(s, 99).k).toBe(5);
    expect(construction.shown(s, -1).is('points')).toBe(true);
  });

  it('finds the step that reveals a name', () => {
    expect(construction.stepOf({ n: 3 }, 'polygon')).toBe(1);
    expect(construction.stepOf({ n: 3 }, 'level', 3)).toBe(4);
    expect(construction.stepOf({ n: 3 }, 'curve')).toBe(5);
  });

  it('keeps a script shown to its end at its end after an edit, else the step', () => {
    expect(construction.keepEnd({ n: 3 }, 5, { n: 4 })).toBe(6);
    expect(construction.keepEnd({ n: 3 }, 2, { n: 4 })).toBe(2);
    expect(construction.keepEnd({ n: 4 }, 5, { n: 2 })).toBe(4);
    const edit = script<S & { k: number }, M, 'a' | 'b'>(
      step('a', 'A'),
      repeat('b', (s) => s.n, 'B'),
    );
    expect(edit.keptAtEnd({ n: 2, k: 2 }, { n: 3, k: 2 }, 'k')).toEqual({ n: 3, k: 3 });
    expect(edit.keptAtEnd({ n: 2, k: 1 }, { n: 3, k: 1 }, 'k')).toEqual({ n: 3, k: 1 });
  });

  it('refuses a name used twice', () => {
    expect(() => script<S, M, 'a'>(step('a', 'one'), step('a', 'two'))).toThrow(/used twice/);
  });

  it('every step reveals one more thing than the step before (property)', () => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 12 }), (n) => {
        const s = { n };
        for (let k = 1; k <= construction.lastStep(s); k++) {
          const before = construction.shown(s, k - 1);
          const now = construction.shown(s, k);
          const total = (x: typeof now) =>
            (['points', 'polygon', 'level', 'curve'] as const).reduce(
              (t, name) => t + x.count(name),
              0,
            );
          expect(total(now)).toBe(total(before) + 1);
        }
      }),
    );
  });

  it('gives two Revealed the same key exactly when they show the same (property)', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 0, max: 6 }),
        fc.integer({ min: 0, max: 6 }),
        fc.integer({ min: 0, max: 9 }),
        fc.integer({ min: 0, max: 9 }),
        (n1, n2, k1, k2) => {
          const [a, b] = [construction.shown({ n: n1 }, k1), construction.shown({ n: n2 }, k2)];
          const names = ['points', 'polygon', 'level', 'curve'] as const;
          const same =
            a.k === b.k &&
            a.lastStep === b.lastStep &&
            a.name === b.name &&
            a.index === b.index &&
            names.every((name) => a.count(name) === b.count(name));
          expect(a.key === b.key).toBe(same);
          // Made once: the same string each time it is read.
          expect(a.key).toBe(a.key);
        },
      ),
    );
    // Level 2 of 3 and level 2 of 4 are the same press in different scripts.
    expect(construction.shown({ n: 3 }, 3).key).not.toBe(construction.shown({ n: 4 }, 3).key);
  });
});
