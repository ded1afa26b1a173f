import { describe, expect, it } from 'vitest';
import type { Point } from '../math';
import { pointList } from './pointList';

interface S {
  p: Point[];
  step: number;
}
const list = pointList<S>({
  id: 'p',
  get: (s) => s.p,
  set: (s, p) => ({ ...s, p }),
  label: (i) => `P_{${i}}`,
  min: 2,
  max: 4,
  // The first point stays on the x-axis.
  constrain: (_s, i, to) => (i === 0 ? [to[0], 0] : to),
  after: (before, after) => ({ ...after, step: before.step === 9 ? 10 : before.step }),
});
const s: S = {
  p: [
    [0, 0],
    [2, 2],
    [4, 0],
  ],
  step: 1,
};

describe('a declared point list', () => {
  it('gives handles with ids, lecture names and positions', () => {
    expect(list.handles(s).map((h) => [h.id, h.label, h.position])).toEqual([
      ['p0', 'P_{0}', [0, 0]],
      ['p1', 'P_{1}', [2, 2]],
      ['p2', 'P_{2}', [4, 0]],
    ]);
  });

  it('names points on one spot once, and keeps each one’s own name for its handle', () => {
    const stacked = list.handles({
      ...s,
      p: [
        [1, 1],
        [1, 1],
        [4, 0],
      ],
    });
    expect(stacked.map((h) => [h.label, h.showLabel])).toEqual([
      ['P_{0} = P_{1}', true],
      ['P_{1}', false],
      ['P_{2}', true],
    ]);
  });

  it('tells its own handles from others by a typed reference', () => {
    expect(list.ref('p12')).toEqual({ list: 'p', index: 12 });
    expect(list.ref('d1')).toBeNull();
    expect(list.ref('p')).toBeNull();
  });

  it('moves a point under its constraint', () => {
    expect(list.move(s, 0, [1, 5]).p[0]).toEqual([1, 0]);
    expect(list.move(s, 1, [1, 5]).p[1]).toEqual([1, 5]);
    // A new state, the old one untouched.
    expect(s.p[1]).toEqual([2, 2]);
  });

  it('adds into the nearest edge and removes, within its limits, then adjusts the state', () => {
    const added = list.add({ ...s, step: 9 }, [3, 1.2])!;
    expect(added.p).toEqual([
      [0, 0],
      [2, 2],
      [3, 1.2],
      [4, 0],
    ]);
    expect(added.step).toBe(10);
    expect(list.add(added, [5, 5])).toBeNull();
    expect(list.remove(s, 1)!.p).toEqual([
      [0, 0],
      [4, 0],
    ]);
    expect(list.remove({ ...s, p: s.p.slice(0, 2) }, 0)).toBeNull();
  });
});

describe('labels of many points', () => {
  it('groups 5000 points by spot in linear time', () => {
    const many = pointList<S>({
      ...{ id: 'v' },
      get: (s) => s.p,
      set: (s, p) => ({ ...s, p }),
      label: (i) => `P_{${i}}`,
      min: 0,
      max: 9999,
    });
    const p = Array.from({ length: 5000 }, (_, i) => [i % 4999, 0]);
    const start = performance.now();
    const handles = many.handles({ p, step: 0 });
    // Points 0 and 4999 share a spot: one label names both.
    expect(handles[0].label).toBe('P_{0} = P_{4999}');
    expect(handles[4999].showLabel).toBe(false);
    expect(performance.now() - start).toBeLessThan(200);
  });
});

describe('points in space', () => {
  it('share a label only where every coordinate agrees (stacked in plan is not one spot)', () => {
    const net = pointList<S>({
      id: 'x',
      get: (s) => s.p,
      set: (s, p) => ({ ...s, p }),
      label: (i) => `x_{${i}}`,
      min: 0,
      max: 9,
    });
    const handles = net.handles({
      p: [
        [1, 1, 0],
        [1, 1, 5],
        [1, 1, 0],
      ],
      step: 0,
    });
    expect(handles.map((h) => [h.label, h.showLabel])).toEqual([
      ['x_{0} = x_{2}', true],
      ['x_{1}', true],
      ['x_{2}', false],
    ]);
  });
});
