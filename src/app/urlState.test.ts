import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bool, choice, formatNumber, int, linkKey, number, numbers, points } from './fields';
import {
  MAX_QUERY_LENGTH,
  type Schema,
  decodeState,
  defaultsOf,
  encodeState,
  practiceQuery,
  withPractice,
} from './urlState';

type Point2 = readonly number[];

interface Demo {
  p: Point2[];
  t: number;
  step: number;
  split: boolean;
  mode: 'natural' | 'closed';
  w: number[];
}

const schema: Schema<Demo> = {
  p: points({
    default: [
      [0, 0],
      [1, 2],
      [3, 2],
      [4, 0],
    ],
    min: 2,
    max: 12,
  }),
  t: number({ default: 0.5, min: 0, max: 1 }),
  step: int({ default: 0, min: 0, max: 11 }),
  split: bool({ default: false }),
  mode: choice({ default: 'natural', values: ['natural', 'closed'] as const }),
  w: numbers({ default: [1, 1], min: 1, max: 5, low: 0.01, high: 100 }),
};

const coordinate = fc.double({ min: -1e6, max: 1e6, noNaN: true, noDefaultInfinity: true });
const state: fc.Arbitrary<Demo> = fc.record({
  p: fc
    .array(fc.tuple(coordinate, coordinate), { minLength: 2, maxLength: 12 })
    .map((ps) => ps.map((q) => [q[0], q[1]] as Point2)),
  t: fc.double({ min: 0, max: 1, noNaN: true }),
  step: fc.integer({ min: 0, max: 11 }),
  split: fc.boolean(),
  mode: fc.constantFrom('natural' as const, 'closed' as const),
  w: fc.array(fc.double({ min: 0.01, max: 100, noNaN: true }), { minLength: 1, maxLength: 5 }),
});

/** What the link keeps of a number: ten significant digits. */
const linked = (v: number) => Number(formatNumber(v));

describe('URL state', () => {
  it('writes a compact, readable query', () => {
    expect(encodeState(schema, defaultsOf(schema))).toBe(
      'p=0,0;1,2;3,2;4,0&t=0.5&step=0&split=0&mode=natural&w=1,1',
    );
  });

  it('state → URL → state is the identity (to the digits a link keeps)', () => {
    fc.assert(
      fc.property(state, (s) => {
        const decoded = decodeState(schema, encodeState(schema, s));
        expect(decoded.issues).toEqual([]);
        expect(decoded.state).toEqual({
          ...s,
          p: s.p.map((q) => [linked(q[0]), linked(q[1])]),
          t: linked(s.t),
          w: s.w.map(linked),
          // -0 becomes 0 in text; equal as numbers.
        });
        // And encoding is stable from then on.
        expect(encodeState(schema, decoded.state)).toBe(encodeState(schema, s));
      }),
    );
  });

  it('keeps ten significant digits', () => {
    expect(formatNumber(0.1 + 0.2)).toBe('0.3');
    expect(formatNumber(1 / 3)).toBe('0.3333333333');
    expect(formatNumber(-2)).toBe('-2');
    expect(formatNumber(1e-7)).toBe('1e-7');
  });

  it('an empty query gives the defaults with no notice', () => {
    expect(decodeState(schema, '')).toEqual({
      state: defaultsOf(schema),
      issues: [],
      views: {},
      scene: 0,
      sceneNamed: false,
      given: new Set(),
      practice: null,
    });
  });

  it('keeps the valid fields of a damaged link and says what it ignored', () => {
    const { state: s, issues } = decodeState(
      schema,
      'p=0,0;2,2;4,0&t=oops&step=3&mode=closed&split=maybe&zzz=1',
    );
    expect(s.p).toEqual([
      [0, 0],
      [2, 2],
      [4, 0],
    ]);
    expect(s.t).toBe(0.5);
    expect(s.step).toBe(3);
    expect(s.mode).toBe('closed');
    expect(s.split).toBe(false);
    expect(issues).toEqual([
      't: "oops" is not a number; the default was used',
      'split: "maybe" is not 0 or 1; the default was used',
      'unknown setting "zzz"',
    ]);
  });

  const hostile: [string, string, RegExp][] = [
    ['script tag', 'p=<script>alert(1)</script>', /characters that do not belong/],
    ['NaN', 'p=NaN,1;2,3', /not a point of two numbers/],
    ['Infinity', 't=Infinity', /not a number/],
    ['1e99', 'p=1e99,0;1,1', /beyond ±1000000/],
    ['1e99 for t', 't=1e99', /outside 0 to 1/],
    ['too few points', 'p=1,1', /1 point given, at least 2 needed/],
    ['a word for the points', 'p=garbage', /"garbage" is not a point x,y/],
    ['too many points', `p=${'1,1;'.repeat(12)}1,1`, /13 points given, at most 12 allowed/],
    ['three coordinates', 'p=1,2,3;4,5', /not a point x,y/],
    ['fraction for an integer', 'step=1.5', /not a whole number/],
    ['negative integer', 'step=-3', /outside 0 to 11/],
    ['bad enum', 'mode=__proto__', /not one of natural, closed/],
    ['hex', 't=0x1', /not a number/],
    ['bad escape', 'p=%E0%A4%A', /not readable/],
    ['prototype key', '__proto__=1', /unknown setting/],
  ];
  for (const [name, query, why] of hostile) {
    it(`rejects a hostile field: ${name}`, () => {
      const { state: s, issues } = decodeState(schema, query);
      expect(s).toEqual(defaultsOf(schema));
      expect(issues).toHaveLength(1);
      expect(issues[0]).toMatch(why);
      expect(Object.getPrototypeOf(s)).toBe(Object.prototype);
    });
  }

  it('ignores an absurdly long state as a whole', () => {
    const query = `p=${Array.from({ length: 100000 }, (_, i) => `${i},0`).join(';')}`;
    expect(query.length).toBeGreaterThan(MAX_QUERY_LENGTH);
    const { state: s, issues } = decodeState(schema, query);
    expect(s).toEqual(defaultsOf(schema));
    expect(issues[0]).toMatch(/all of it was ignored/);
  });

  it('never throws and never returns a non-finite number, whatever the string', () => {
    fc.assert(
      fc.property(fc.string({ maxLength: 300 }), (query) => {
        const { state: s } = decodeState(schema, query);
        for (const q of s.p) expect(q.every(Number.isFinite)).toBe(true);
        expect(Number.isFinite(s.t)).toBe(true);
        expect(s.p.length).toBeGreaterThanOrEqual(2);
      }),
    );
  });

  it('defaults are fresh copies, never shared with the schema', () => {
    const a = defaultsOf(schema);
    (a.p[0] as unknown as number[])[0] = 99;
    expect(defaultsOf(schema).p[0][0]).toBe(0);
  });
});

describe('figure views in the link', () => {
  it('reads the view of a named figure apart from the state, and reports one of an unknown figure', () => {
    const decoded = decodeState(schema, 't=0.25&view.map=1,2,80&view.nope=1,2,3', ['map']);
    expect(decoded.state.t).toBe(0.25);
    expect(decoded.views).toEqual({ map: '1,2,80' });
    expect(decoded.issues).toEqual(['unknown setting "view.nope"']);
  });

  it('writes the views after the state, so a prepared link opens the picture shared', () => {
    const query = encodeState(schema, defaultsOf(schema), { map: '1,2,80' });
    expect(query.endsWith('&view.map=1,2,80')).toBe(true);
    expect(decodeState(schema, query, ['map']).views).toEqual({ map: '1,2,80' });
  });
});

describe('link keys apart from field names', () => {
  const schema: Schema<{ points: Point2[]; parameter: number }> = {
    points: linkKey(points({ default: [[0, 0]], min: 1, max: 4 }), 'p'),
    parameter: linkKey(number({ default: 0.5, min: 0, max: 1 }), 't', 'mu'),
  };
  it('writes the short key and reads it back into the named field', () => {
    const query = encodeState(schema, {
      points: [
        [1, 2],
        [3, 4],
      ],
      parameter: 0.25,
    });
    expect(query).toBe('p=1,2;3,4&t=0.25');
    expect(decodeState(schema, query).state).toEqual({
      points: [
        [1, 2],
        [3, 4],
      ],
      parameter: 0.25,
    });
  });
  it('reads an earlier key as an alias, and a field given under two keys once', () => {
    expect(decodeState(schema, 'mu=0.75').state.parameter).toBe(0.75);
    const twice = decodeState(schema, 't=0.1&mu=0.9');
    expect(twice.state.parameter).toBe(0.1);
    expect(twice.issues).toEqual(['"mu" given twice; the first was kept']);
  });
});

describe("an exercise's link (ex and seed)", () => {
  const exercises = ['where', 'weight'];
  it('reads the exercise and its seed, and writes them back', () => {
    const decoded = decodeState(schema, 'ex=weight&seed=4242', [], [], exercises);
    expect(decoded.issues).toEqual([]);
    expect(decoded.practice).toEqual({ id: 'weight', seed: 4242, kept: false });
    expect(practiceQuery({ id: 'weight', seed: 4242 })).toBe('ex=weight&seed=4242');
    expect(withPractice({ id: 'weight', seed: 4242 }, 't=0.3')).toBe('ex=weight&seed=4242&t=0.3');
    expect(withPractice(null, 't=0.3')).toBe('t=0.3');
  });
  it('a link that also carries the figure keeps it (the student’s own work)', () => {
    const decoded = decodeState(schema, 'ex=weight&seed=7&t=0.25', [], [], exercises);
    expect(decoded.practice).toEqual({ id: 'weight', seed: 7, kept: true });
    expect(decoded.state.t).toBe(0.25);
  });
  it('an exercise without a seed opens with seed 1', () => {
    expect(decodeState(schema, 'ex=where', [], [], exercises).practice).toEqual({
      id: 'where',
      seed: 1,
      kept: false,
    });
  });
  it('an unknown exercise or a bad seed is named, and the lesson opens as usual', () => {
    const unknown = decodeState(schema, 'ex=nope&seed=3', [], [], exercises);
    expect(unknown.practice).toBeNull();
    expect(unknown.issues.join(' ')).toMatch(/"nope" is not an exercise/);
    const bad = decodeState(schema, 'ex=where&seed=-5', [], [], exercises);
    expect(bad.practice).toEqual({ id: 'where', seed: 1, kept: false });
    expect(bad.issues.join(' ')).toMatch(/seed: "-5" is not a whole number/);
    const big = decodeState(schema, 'ex=where&seed=1234567', [], [], exercises);
    expect(big.issues.join(' ')).toMatch(/not a whole number from 1 to 999999/);
  });
  it('a lesson without exercises calls ex an unknown setting', () => {
    expect(decodeState(schema, 'ex=where').issues.join(' ')).toMatch(/unknown setting "ex"/);
  });
});
