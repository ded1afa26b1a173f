import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import lesson from './lesson';
import type { RoadModel } from './model';
import { valleyVillages } from './scenes';
import { type RoadState, normalize, schema } from './state';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: RoadState) => lesson.derive(s) as RoadModel;
const map = lesson.figures[0];

const state = (change: Partial<RoadState>): RoadState =>
  normalize({ ...defaultsOf(schema), ...change }).state;

/** Each step's name, with its repeat where it repeats (`sweep 2`). */
function names(s: RoadState): string[] {
  const last = lesson.steps!.count(s);
  return Array.from({ length: last + 1 }, (_, step) => {
    const { name, index } = derive({ ...s, step }).shown;
    return index ? `${name} ${index}` : name;
  });
}

const times = (name: string, n: number) => Array.from({ length: n }, (_, i) => `${name} ${i + 1}`);

describe('the road’s script: each step named after what it reveals', () => {
  it('natural and clamped: the villages, the system, its forward sweep, its back substitution', () => {
    const expected = ['villages', 'system 1', ...times('sweep', 6), ...times('substitution', 6)];
    expect(names(state({}))).toEqual(expected);
    expect(names(state({ road: 'clamped' }))).toEqual(expected);
    // 500 villages in chunks of 56 rows: 9 presses each way.
    const valley = state({ villages: valleyVillages(500) });
    expect(names(valley)).toEqual([
      'villages',
      'system 1',
      ...times('sweep', 9),
      ...times('substitution', 9),
    ]);
  });

  it('the others: their construction (none for the Roman road), then the segments from P0', () => {
    expect(names(state({ road: 'roman' }))).toEqual(['villages', ...times('segments', 5)]);
    expect(names(state({ road: 'quadratic' }))).toEqual([
      'villages',
      'construction 1',
      ...times('segments', 5),
    ]);
    expect(names(state({ road: 'hermite' }))).toEqual([
      'villages',
      'construction 1',
      ...times('segments', 5),
    ]);
    // The ring road has one more segment, back to P0.
    expect(names(state({ road: 'ring' }))).toEqual([
      'villages',
      'construction 1',
      ...times('segments', 6),
    ]);
  });

  it('a segment step names every segment the figure shows built, from P0, and the new ones', () => {
    // The quadratic road: villages, its construction, then one segment of 5 a press.
    const road = state({ road: 'quadratic' });
    const say = (step: number) => lesson.steps!.describe({ ...road, step }, step);
    expect(say(2)).toBe('Built so far: segment 0 of the 5');
    expect(say(3)).toBe('Built so far: segments 0–1 of the 5 (new: segment 1)');
    expect(say(5)).toBe('Built so far: segments 0–3 of the 5 (new: segment 3)');
    expect(say(6)).toBe('The whole road: p̄ runs from 0 at P₀ to 5 at P₅');
    // The figure draws segments 0 … 1 at step 3: the road up to P2.
    expect(derive({ ...road, step: 3 }).shown.index).toBe(2);
  });

  it('the overlay: one answer a press, whatever the method', () => {
    expect(names(state({ view: 'compare', compare: [6, 0, 3] }))).toEqual([
      'villages',
      ...times('answer', 3),
    ]);
    // With no answer ticked the overlay keeps one step, and says why nothing is drawn.
    const none = state({ view: 'compare', compare: [], step: 1 });
    expect(names(none)).toEqual(['villages', 'answer 1']);
    expect(lesson.steps!.describe(none, 1)).toBe('No answer is ticked to draw side by side');
  });

  it('gives each step of the solve its formula for x, and none to the villages or the overlay', () => {
    const formula = (s: RoadState) => lesson.steps!.formula!(derive(s), s);
    expect(formula(state({ step: 0 }))).toBeNull();
    expect(formula(state({ view: 'compare', step: 2 }))).toBeNull();
    // Row 1 of the six villages' system for x: 1·D0 + 4·D1 + 1·D2 = 3(x2 − x0) = 126.
    expect(formula(state({ step: 1 }))).toBe(
      '\\text{row } 1,\\ x:\\quad 1\\,D_{0} + 4\\,D_{1} + 1\\,D_{2} = 126',
    );
    expect(formula(state({ road: 'quadratic', step: 1 }))).toBe(
      'D_0 = (30.00,\\ 0.00),\\quad B_0 = P_0 + \\tfrac12 D_0 = (15.00,\\ 0.00)',
    );
  });

  it('a step changes what is shown, not the solve: the geometry is kept', () => {
    const a = derive(state({ step: 3 }));
    // A clicker press: the same villages and choices, another step.
    const b = derive({ ...a.state, step: 4 });
    expect(b.solve).toBe(a.solve);
    expect(b.road).toBe(a.road);
    expect(a.progress).toEqual({ swept: 2, fixed: 0, row: 1 });
    expect(b.progress).toEqual({ swept: 3, fixed: 0, row: 2 });
  });
});

describe('the villages, declared once', () => {
  const lecture = state({ step: 13 });

  it('are handles after the gradients and the marker, each with its own label', () => {
    const clamped = state({ road: 'clamped', step: 13 });
    expect(map.handles!(derive(clamped)).map((h) => h.id)).toEqual([
      'a',
      'b',
      's',
      'p0',
      'p1',
      'p2',
      'p3',
      'p4',
      'p5',
    ]);
    const same = state({
      villages: [
        [0, 0],
        [42, 10],
        [42, 10],
        [78, 26],
      ],
    });
    const labels = map.handles!(derive(same)).filter((h) => h.id.startsWith('p'));
    expect(labels.map((h) => [h.label, h.showLabel])).toEqual([
      ['P_{0}', true],
      ['P_{1}', true],
      ['P_{2}', true],
      ['P_{3}', true],
    ]);
    // Beyond 40 villages they are dots on the road, unlabelled.
    const many = map.handles!(derive(state({ villages: valleyVillages(41) })));
    expect(many.filter((h) => h.id.startsWith('p')).every((h) => h.dot && !h.showLabel)).toBe(true);
  });

  it('a new village is kept to 0.01 and goes into the nearest stretch of road', () => {
    const added = map.addPoint!(lecture, [50.123, 20.456], derive(lecture))!;
    expect(added.villages[3]).toEqual([50.12, 20.46]);
    expect(added.villages).toHaveLength(7);
  });

  it('a road shown to its end stays shown to its end after an edit', () => {
    const added = map.addPoint!(lecture, [50, 20], derive(lecture))!;
    expect(added.step).toBe(lesson.steps!.count(added));
    expect(added.step).toBe(15);
    const removed = map.removeHandle!(lecture, 'p1', derive(lecture))!;
    expect(removed.step).toBe(11);
    // Midway, the step stays where it was.
    const midway = state({ step: 4 });
    expect(map.addPoint!(midway, [50, 20], derive(midway))!.step).toBe(4);
  });
});

describe('the view in the link (`overlay`, as before)', () => {
  const field = schema.view;

  it('writes the road alone and the comparison as 0 and 1, as the overlay did', () => {
    expect(field.key).toBe('overlay');
    expect(field.default).toBe('road');
    expect(
      ['road', 'compare', 'derivation', 'global'].map((v) => field.encode(v as never)),
    ).toEqual(['0', '1', 'derivation', 'global']);
  });

  it('reads what the yes/no overlay read, and the two new views', () => {
    const read = (raw: string) => field.decode(raw);
    expect(read('0')).toEqual({ ok: true, value: 'road' });
    expect(read('false')).toEqual({ ok: true, value: 'road' });
    expect(read('1')).toEqual({ ok: true, value: 'compare' });
    expect(read('true')).toEqual({ ok: true, value: 'compare' });
    expect(read('derivation')).toEqual({ ok: true, value: 'derivation' });
    expect(read('global')).toEqual({ ok: true, value: 'global' });
    expect(read('2')).toEqual({ ok: false, why: '"2" is not 0, 1, derivation or global' });
  });

  it('says which scene a state is in, and keeps the derivation and global views natural', () => {
    expect(lesson.sceneOf!(state({}))).toBe('lecture');
    expect(lesson.sceneOf!(state({ view: 'compare' }))).toBe('compare');
    expect(lesson.sceneOf!(state({ view: 'derivation' }))).toBe('derivation');
    expect(lesson.sceneOf!(state({ view: 'global' }))).toBe('global');
    const fixed = normalize({ ...defaultsOf(schema), view: 'derivation', road: 'ring' });
    expect(fixed.state.road).toBe('natural');
    expect(fixed.issues).toEqual([
      'road: the derivation view is of the natural spline, so road=natural',
    ]);
  });

  it('names the first scene after its villages, not the lecture', () => {
    expect(lesson.scenes!.map((s) => [s.id, s.label]).slice(0, 1)).toEqual([
      ['lecture', 'Six villages inland'],
    ]);
    expect(lesson.scenes!.slice(-2).map((s) => s.id)).toEqual(['derivation', 'global']);
  });
});
