import { describe, expect, it } from 'vitest';
import { decodeState } from '../../app/urlState';
import { curvatureHref } from '../../kit/lessonLinks';
import { schema } from './state';

// The kit writes links into this lesson without importing it: they must read
// back through this lesson's own schema, value for value, with no issues.
describe('links into the curvature lesson', () => {
  it('read back through the schema as handed over', () => {
    const p = [
      [0, 0],
      [1.25, 2],
      [3, -0.3333333333333333],
      [4, 0],
    ];
    const d = [
      [1, 0],
      [0, 1],
    ];
    const href = curvatureHref({ src: 'hermite', p, d, t: 1.7 })!;
    expect(href).toBe(
      '#/curvature?part=plane&src=hermite&p=0,0;1.25,2;3,-0.3333333333;4,0&d=1,0;0,1&t=1&step=4',
    );
    const { state, issues } = decodeState(schema, href.slice(href.indexOf('?') + 1));
    expect(issues).toEqual([]);
    expect(state).toMatchObject({ part: 'plane', source: 'hermite', gradients: d, t: 1, step: 4 });
    expect(state.points.map((q) => q.map((v) => v.toFixed(9)))).toEqual(
      p.map((q) => q.map((v) => v.toFixed(9))),
    );
    // Each field under the key the link carries, as the schema writes it.
    for (const [field, key] of [
      ['source', 'src'],
      ['points', 'p'],
      ['gradients', 'd'],
    ] as const) {
      expect(schema[field].key).toBe(key);
      expect(href).toContain(`${key}=${schema[field].encode(state[field] as never)}`);
    }
  });

  it('is null for a curve the lesson cannot take', () => {
    expect(curvatureHref({ src: 'bezier', p: [[0, 0]] })).toBeNull();
    const many = Array.from({ length: 41 }, (_, i) => [i, 0]);
    expect(curvatureHref({ src: 'chain', p: many })).toBeNull();
  });
});
