import { describe, expect, it } from 'vitest';
import { choice, int, linkKey, points } from '../app/fields';
import { normalizeState } from '../app/lessonState';
import type { Point } from '../math';
import { defineLesson } from './lesson';
import { pointList } from './pointList';
import { type Revealed, script, step } from './script';

interface S {
  part: 'a' | 'b';
  p: Point[];
  step: number;
}
interface M {
  state: S;
  shown: Revealed<string>;
}
const schema = {
  part: choice<'a' | 'b'>({ default: 'a', values: ['a', 'b'] }),
  p: points({
    default: [
      [0, 0],
      [1, 1],
      [2, 0],
    ],
    min: 2,
    max: 5,
  }),
  step: int({ default: 0, min: 0, max: 9 }),
};
const list = (min: number, max: number) =>
  pointList<S>({
    id: 'p',
    get: (s) => s.p,
    set: (s, p) => ({ ...s, p }),
    label: (i) => `P_{${i}}`,
    min,
    max,
  });
let derived = 0;
const make = (min: number, max: number) =>
  defineLesson<S, M, string>({
    slug: 'demo',
    schema,
    step: 'step',
    sceneOf: (s) => s.part,
    derive: (state, shown) => {
      derived++;
      return { state, shown };
    },
    scenes: [
      {
        id: 'a',
        label: 'A',
        setup: (s) => ({ ...s, part: 'a' }),
        script: script(
          step('one', 'First of A'),
          step('two', 'Second of A', () => 'x = 1'),
        ),
      },
      {
        id: 'b',
        label: 'B',
        setup: (s) => ({ ...s, part: 'b' }),
        figures: ['plane'],
        script: script(step('only', ({ state }) => `B with ${state.p.length} points`)),
      },
    ],
    figures: [
      {
        id: 'plane',
        title: 'Plane',
        kind: 'geometry',
        bounds: () => ({ minX: 0, maxX: 1, minY: 0, maxY: 1 }),
        draw: () => {},
        points: [list(min, max)],
        addTo: list(min, max),
      },
    ],
    panel: () => ({ element: null as unknown as HTMLElement, update: () => {} }),
  });
const a: S = { part: 'a', p: schema.p.default.map((q) => [...q]), step: 1 };

describe('a lesson made of the kit', () => {
  it('takes each scene’s steps from its own script, with the model', () => {
    const lesson = make(2, 5);
    expect(lesson.steps!.count(a)).toBe(1);
    expect(lesson.steps!.describe(a, 1)).toBe('Second of A');
    expect(lesson.steps!.formula!(lesson.derive(a), a)).toBe('x = 1');
    const b: S = { ...a, part: 'b', step: 0 };
    expect(lesson.steps!.count(b)).toBe(0);
    expect(lesson.steps!.describe(b, 0)).toBe('B with 3 points');
  });

  it('derives once per state object, with what the step reveals', () => {
    const lesson = make(2, 5);
    derived = 0;
    const m = lesson.derive(a);
    expect(lesson.derive(a)).toBe(m);
    lesson.steps!.describe(a, 1);
    expect(derived).toBe(1);
    expect(m.shown.has('two')).toBe(true);
    expect(m.shown.is('two')).toBe(true);
  });

  it('shows the figures a scene lists, all where it lists none', () => {
    const lesson = make(2, 5);
    expect(lesson.figuresShown!(a)).toBeNull();
    expect(lesson.figuresShown!({ ...a, part: 'b' })).toEqual(['plane']);
  });

  it('moves, adds and removes through the point list, and offers neither edit to a fixed list', () => {
    const figure = make(2, 5).figures[0];
    const moved = figure.moveHandle!(a, 'p1', [5, 5], { state: a } as M);
    expect(moved.p[1]).toEqual([5, 5]);
    expect(figure.addPoint!(a, [1.5, 0.4], { state: a } as M)!.p).toHaveLength(4);
    expect(figure.removeHandle!(a, 'p0', { state: a } as M)!.p).toEqual([
      [1, 1],
      [2, 0],
    ]);
    const fixed = make(3, 3).figures[0];
    expect(fixed.addPoint).toBeUndefined();
    expect(fixed.removeHandle).toBeUndefined();
    expect(fixed.handles!({ state: a } as M).map((h) => h.id)).toEqual(['p0', 'p1', 'p2']);
  });

  it('interleaves two lists by index when asked: D0, P0, D1, P1', () => {
    const tips = pointList<S>({
      id: 'd',
      get: (s) => s.p.map(([x, y]) => [x, y + 1]),
      set: (s) => s,
      label: (i) => `D_{${i}}`,
      min: 0,
      max: 0,
    });
    const lesson = make(2, 5);
    const kit = defineLesson<S, M, string>({
      slug: 'demo2',
      schema,
      step: 'step',
      script: script(step('one', 'One')),
      derive: (state, shown) => ({ state, shown }),
      scenes: [{ id: 'a', label: 'A', setup: (s) => s }],
      figures: [
        {
          id: 'plane',
          title: 'Plane',
          kind: 'geometry',
          bounds: () => ({ minX: 0, maxX: 1, minY: 0, maxY: 1 }),
          draw: () => {},
          points: [tips, list(2, 5)],
          interleave: true,
        },
      ],
      panel: lesson.panel,
    });
    expect(kit.figures[0].handles!({ state: a } as M).map((h) => h.id)).toEqual([
      'd0',
      'p0',
      'd1',
      'p1',
      'd2',
      'p2',
    ]);
  });
});

describe('a step past the end, in a link', () => {
  it('is named by its link key in the notice, not by its name in code', () => {
    const lesson = make(2, 5);
    const keyed = { ...lesson, schema: { ...schema, step: linkKey(schema.step, 'k') } };
    const { state, issues } = normalizeState(keyed, { ...a, step: 9 });
    expect(state.step).toBe(1);
    expect(issues).toEqual([
      'k: 9 is past the last step of this construction (1), so it shows step 1',
    ]);
  });
});
