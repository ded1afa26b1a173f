import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import lesson from '../../lessons/de-casteljau/lesson';
import { normalizeState } from '../lessonState';
import { defaultsOf } from '../urlState';
import { pageGeometry, rowsPerPage, tableRows } from './geometry';
import {
  DEFAULT_OPTIONS,
  type Item,
  type PerPage,
  GRID,
  paginate,
  planItems,
  readOptions,
  tablesOf,
  writeOptions,
} from './plan';

const SCENES = ['cubic', 'quadratic', 'loop', 'quintic'];

describe('handout options in the link', () => {
  it('keeps the lesson’s own link exactly and reads its options', () => {
    const read = readOptions(
      'scene=cubic&p=0,0;1,2;3,2;4,0&t=0.4&handout.per-page=6&handout.paper=letter&handout.steps=last&handout.values=own&handout.scenes=loop,cubic',
      SCENES,
    );
    expect(read.lessonQuery).toBe('scene=cubic&p=0,0;1,2;3,2;4,0&t=0.4');
    expect(read.issues).toEqual([]);
    // Scenes in the lesson's order, whatever the link's.
    expect(read.options).toEqual({
      scenes: ['cubic', 'loop'],
      steps: 'last',
      perPage: 6,
      paper: 'letter',
      values: 'own',
    });
    expect(readOptions(`x=1&${writeOptions(read.options)}`, SCENES).options).toEqual(read.options);
  });

  it('writes nothing for the defaults', () => {
    expect(writeOptions(DEFAULT_OPTIONS)).toBe('');
  });

  it('says what it could not use and keeps the defaults', () => {
    const read = readOptions(
      'handout.per-page=5&handout.paper=a3&handout.steps=some&handout.values=then&handout.scenes=nowhere&handout.colour=red',
      SCENES,
    );
    expect(read.options).toEqual(DEFAULT_OPTIONS);
    expect(read.issues).toHaveLength(6);
    expect(read.issues.join(' ')).toMatch(/5 frames a page is not offered/);
    expect(read.issues.join(' ')).toMatch(/No scene called “nowhere”/);
  });
});

describe('the frames of a handout', () => {
  const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;

  it('is every step of every scene, in order, with the lesson’s own captions', () => {
    const scenes = planItems(lesson, defaults, 0, { ...DEFAULT_OPTIONS, steps: 'all' });
    // de Casteljau: a cubic (4 points) and the loop walk 6 steps, the quadratic 5, degree 5 eight,
    // the pseudocode ten and the Bernstein form five.
    expect(scenes.map((s) => s.length)).toEqual([6, 5, 6, 8, 10, 5]);
    const loop = scenes[2];
    expect(loop.map((f) => f.step)).toEqual([0, 1, 2, 3, 4, 5]);
    for (const frame of loop)
      expect(frame.caption).toBe(lesson.steps!.describe(frame.state as never, frame.step));
    expect(loop[0].caption).toMatch(/P₀ … P₃/);
  });

  it('is each scene’s last step only, when asked', () => {
    const scenes = planItems(lesson, defaults, 0, { ...DEFAULT_OPTIONS, steps: 'last' });
    expect(scenes.map((s) => s.map((f) => `${f.step}/${f.last}`))).toEqual([
      ['5/5'],
      ['4/4'],
      ['5/5'],
      ['7/7'],
      ['9/9'],
      ['4/4'],
    ]);
  });

  it('keeps the points on screen now in the current scene, or takes each scene’s own', () => {
    const moved = {
      ...(defaults as object),
      p: [
        [0, 0],
        [1, 3],
        [3, 2],
        [4, 0],
      ],
      t: 0.25,
    };
    const now = planItems(lesson, moved, 0, {
      ...DEFAULT_OPTIONS,
      scenes: ['cubic'],
      steps: 'last',
    });
    const own = planItems(lesson, moved, 0, {
      ...DEFAULT_OPTIONS,
      scenes: ['cubic'],
      steps: 'last',
      values: 'own',
    });
    // P(0.25) of (0,0), (1,3), (3,2), (4,0) by hand: 3·0.75²·0.25·(1,3) + 3·0.75·0.25²·(3,2) + 0.25³·(4,0)
    // = (0.421875 + 0.421875 + 0.0625, 1.265625 + 0.28125) = (0.90625, 1.546875).
    expect(now[0][0].formula).toMatch(/P\(0\.25\)/);
    expect(now[0][0].formula).toMatch(/0\.906,\\ 1\.547/);
    // The scene's own t is Figure 5's, 0.6.
    expect(own[0][0].formula).toMatch(/P\(0\.6\)/);
  });

  it('puts the construction’s points in a table under the scene’s last frame', () => {
    const [cubic] = planItems(lesson, defaults, 0, { ...DEFAULT_OPTIONS, steps: 'last' });
    const [table] = tablesOf(lesson, cubic[0], 100);
    expect(table.table.rows).toHaveLength(10);
    // P₃,₀ = P(0.6) = 0.288·(1, 2) + 0.432·(3, 2) + 0.216·(4, 0) = (2.448, 1.44), by hand.
    expect(table.table.rows.at(-1)).toEqual(['3', 'P₃,₀', '2.4480', '1.4400']);
    const parts = tablesOf(lesson, cubic[0], 4);
    expect(parts.map((p) => [p.part, p.parts, p.table.rows.length])).toEqual([
      [0, 3, 4],
      [1, 3, 4],
      [2, 3, 2],
    ]);
  });
});

describe('pages', () => {
  const frame = (i: number): Item => ({ kind: 'frame', i }) as unknown as Item;
  const table = (rows: number): Item => ({ kind: 'table', rows }) as unknown as Item;
  const rowsOf = (t: { rows?: number }) => (t as { rows: number }).rows;

  it('fills 2 × 2 frames a page, and a table starts a fresh row across the page', () => {
    const pages = paginate([frame(0), frame(1), frame(2), table(1), frame(3)], 4, rowsOf as never);
    expect(pages.map((p) => p.map((x) => [x.row, x.column, x.rowSpan]))).toEqual([
      [
        [0, 0, 1],
        [0, 1, 1],
        [1, 0, 1],
      ],
      [
        [0, 0, 1],
        [1, 0, 1],
      ],
    ]);
  });

  it('never lets an item cross a page or share a cell, never leaves a page empty, keeps the order', () => {
    const item = fc.oneof(
      fc.constant(frame(0)),
      fc.integer({ min: 1, max: 4 }).map((rows) => table(rows)),
    );
    fc.assert(
      fc.property(
        fc.array(item, { maxLength: 40 }),
        fc.constantFrom<PerPage>(1, 2, 4, 6),
        (items, per) => {
          const { rows, columns } = GRID[per];
          const pages = paginate(items, per, rowsOf as never);
          expect(pages.flat().map((p) => p.item)).toEqual(items);
          for (const page of pages) {
            expect(page.length).toBeGreaterThan(0);
            const taken = new Set<string>();
            for (const p of page) {
              expect(p.row + p.rowSpan).toBeLessThanOrEqual(rows);
              const span = p.item.kind === 'table' ? columns : 1;
              for (let r = p.row; r < p.row + p.rowSpan; r++)
                for (let c = p.column; c < p.column + span; c++) {
                  expect(taken.has(`${r},${c}`)).toBe(false);
                  taken.add(`${r},${c}`);
                }
            }
          }
          if (items.every((i) => i.kind === 'frame'))
            expect(pages.length).toBe(Math.ceil(items.length / per));
        },
      ),
    );
  });

  it('has A4 and Letter geometry that adds up', () => {
    // A4: 297 mm − 2 × 12 margin − 30 head − 7 foot = 236 mm; two rows with a 4 mm gap: 116 mm each.
    const a4 = pageGeometry('a4', 4);
    expect(a4.cell.height).toBeCloseTo(116, 6);
    expect(a4.cell.width).toBeCloseTo((210 - 24 - 4) / 2, 6);
    const letter = pageGeometry('letter', 6);
    expect(letter.cell.height).toBeCloseTo((279.4 - 24 - 37 - 8) / 3, 6);
    // A 21-row table (7 mm title + 22 rows of 4.6 mm = 108.2 mm) fits one 116 mm row.
    expect(tableRows(a4, 21)).toBe(1);
    expect(tableRows(a4, 30)).toBe(2);
    expect(rowsPerPage(a4)).toBe(Math.floor((236 - 7) / 4.6) - 1);
  });
});
