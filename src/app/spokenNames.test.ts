import { describe, expect, it } from 'vitest';
import type { Handle } from './lesson';
import { SpokenNames } from './spokenNames';

const handle = (label: string, position: number[]): Handle =>
  ({ id: label, label, position }) as unknown as Handle;

describe('the names a screen reader hears for handles', () => {
  it('says each label and its point to two decimals, subscripts written plain', () => {
    const names = new SpokenNames();
    expect(names.of([handle('P_{1,2}', [1, -2.5]), handle('P_0', [0.125, 3])])).toEqual([
      'P1,2 at (1.00, -2.50)',
      'P0 at (0.13, 3.00)',
    ]);
  });

  it('keeps the names of handles that did not move, and names again the one that did', () => {
    const names = new SpokenNames();
    const first = names.of([handle('P_0', [0, 0]), handle('P_1', [1, 1])]);
    const second = names.of([handle('P_0', [0, 0]), handle('P_1', [2, 1])]);
    expect(second[0]).toBe(first[0]);
    expect(second[1]).toBe('P1 at (2.00, 1.00)');
    // A point taken out: the list shifts, and each handle is named for what it is now.
    expect(names.of([handle('P_1', [2, 1])])).toEqual(['P1 at (2.00, 1.00)']);
    // Another label at the same place is another name.
    expect(names.of([handle('Q_1', [2, 1])])).toEqual(['Q1 at (2.00, 1.00)']);
  });
});
