import { describe, expect, it } from 'vitest';
import bsplines from '../../lessons/b-splines/lesson';
import surface from '../../lessons/surface/lesson';
import { normalizeState } from '../lessonState';
import { defaultsOf } from '../urlState';
import { DEFAULT_OPTIONS, planItems, tablesOf } from './plan';
import type { AnyLesson } from '../lesson';

const lastFrames = (lesson: AnyLesson) =>
  planItems(lesson, normalizeState(lesson, defaultsOf(lesson.schema)).state, 0, {
    ...DEFAULT_OPTIONS,
    steps: 'last',
    values: 'own',
  }).map((scene) => scene[0]);

const value = (cell: string) => (cell === '' ? 0 : Number(cell.replace('−', '-')));

describe('the tables a handout prints under a scene', () => {
  it('b-splines: the Cox–de Boor triangle, whose rows each add up to 1 (a partition of unity)', () => {
    const withTriangle = lastFrames(bsplines)
      .map((frame) => ({ frame, tables: tablesOf(bsplines, frame, 100) }))
      .filter(({ tables }) => tables.length > 0);
    // The knot scenes have one; the uniform scenes (a fixed matrix) have none.
    expect(withTriangle.length).toBeGreaterThan(0);
    expect(withTriangle.map(({ frame }) => frame.scene.id)).not.toContain('uniform');
    for (const { frame, tables } of withTriangle) {
      const rows = tables[0].table.rows;
      expect(rows.length, frame.scene.id).toBeGreaterThan(1);
      for (const row of rows) {
        const sum = row.slice(1).reduce((s, cell) => s + value(cell), 0);
        expect(sum, `${frame.scene.id} row ${row[0]}`).toBeCloseTo(1, 3);
        for (const cell of row.slice(1)) expect(value(cell)).toBeGreaterThanOrEqual(0);
      }
    }
  });

  it('surface: the 4 × 4 net, m down and n across, with each point’s three coordinates', () => {
    const [patch] = lastFrames(surface);
    const [net] = tablesOf(surface, patch, 100);
    expect(net.table.columns).toEqual(['', 'n = 0', 'n = 1', 'n = 2', 'n = 3']);
    expect(net.table.rows.map((row) => row[0])).toEqual(['m = 0', 'm = 1', 'm = 2', 'm = 3']);
    const state = patch.state as { net: number[][][] };
    // x(3,3) as the link writes it, to two decimals.
    expect(net.table.rows[3][4]).toBe(
      state.net[3][3]
        .map((v) => v.toFixed(2))
        .join(', ')
        .replaceAll('-', '−'),
    );
  });
});
