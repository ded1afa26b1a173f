import { h, setText } from '../../app/dom';
import { parseNumber } from '../../app/fields';
import { trimmed } from '../../kit/format';
import type { LessonApi, Point } from '../../app/lesson';
import type { SurfaceModel } from './model';
import type { SurfaceState } from './state';

/** Largest coordinate typed into the table (the link accepts up to 1e6). */
const LIMIT = 1e6;

/** A cell's numbers as typed, split at commas, semicolons or spaces. */
const tokens = (text: string): string[] => text.split(/[,;\s]+/).filter((part) => part !== '');

/** "x, y, z" typed by hand → a point, or null if it is not three numbers. */
export function parseTriple(text: string): Point | null {
  const parts = tokens(text);
  if (parts.length !== 3) return null;
  const values = parts.map((part) => parseNumber(part.replace('−', '-')));
  if (values.some((value) => value === null || Math.abs(value) > LIMIT)) return null;
  return values as number[];
}

/** A coordinate as the table shows it: to three decimals, as the figure's labels are. */
const shown = (value: number) => trimmed(value, 3);

/** A point as its cell shows it, "x, y, z" (a dragged point has 17 digits; the cell, three decimals). */
const tripleText = (p: readonly number[]) => p.map(shown).join(', ');

/**
 * What a cell typed as `typed` means for the point `was`: a coordinate left
 * as the cell showed it keeps its exact value, so typing a new z does not
 * round x and y to the cell's three decimals.
 */
export function keepShown(typed: Point, text: string, was: readonly number[]): Point {
  const words = tokens(text);
  return typed.map((value, d) => (words[d] === shown(was[d]) ? was[d] : value));
}

/**
 * The control net as an editable 4 × 4 table: one cell per point, "x, y, z",
 * m down and n across as the slides' xₘ,ₙ (Pₘ,ₙ here, the second net's Qₘ,ₙ).
 * Enter or leaving the cell applies it.
 * A cell that is not three numbers is put back and says so under the table, not in
 * the page's notices: a notice would push the figures down and change their size.
 */
export function netTable(
  api: LessonApi<SurfaceState, SurfaceModel>,
  field: 'net' | 'secondNet',
): { element: HTMLElement; update(state: SurfaceState): void } {
  // The net's letter as the figure names its points: P, and Q for the second patch.
  const name = field === 'net' ? 'P' : 'Q';
  const inputs: HTMLInputElement[][] = [];
  const body = h('tbody', {});
  const message = h('p', { class: 'net-table-message', role: 'status' });
  for (let m = 0; m < 4; m++) {
    const row = h('tr', {}, h('th', { scope: 'row', 'aria-label': `m = ${m}` }, String(m)));
    inputs.push([]);
    for (let n = 0; n < 4; n++) {
      const input = h('input', {
        type: 'text',
        inputmode: 'decimal',
        spellcheck: 'false',
        'aria-label': `${name}${m},${n} (x, y, z)`,
        class: 'net-cell',
      });
      input.addEventListener('change', () => {
        const state = api.get();
        const p = parseTriple(input.value);
        if (!p) {
          setText(
            message,
            `${name}${m},${n}: type three numbers "x, y, z" (each at most ${LIMIT} in size); kept ${tripleText(state[field][m][n])}.`,
          );
          input.value = tripleText(state[field][m][n]);
          return;
        }
        setText(message, '');
        const net = state[field].map((points, i) =>
          points.map((q, j) => (i === m && j === n ? keepShown(p, input.value, q) : q)),
        );
        api.set({ ...state, [field]: net });
      });
      inputs[m].push(input);
      row.append(h('td', {}, input));
    }
    body.append(row);
  }
  const table = h(
    'table',
    {
      class: 'data-table matrix net-table',
      'aria-label': `Control net ${name} (x, y, z of each point)`,
    },
    h(
      'thead',
      {},
      h(
        'tr',
        {},
        // m down and n across, as the weights' grid is headed (m\n): the row
        // heads are a digit wide, and the four columns of "x, y, z" fit a
        // laptop's panel.
        h('th', { scope: 'col' }, 'm\\n'),
        ...[0, 1, 2, 3].map((n) => h('th', { scope: 'col', 'aria-label': `n = ${n}` }, String(n))),
      ),
    ),
    body,
  );
  const element = h('div', {}, table, message);
  return {
    element,
    update(state) {
      state[field].forEach((points, m) =>
        points.forEach((p, n) => {
          const input = inputs[m][n];
          const text = tripleText(p);
          // Never overwrite what someone is typing.
          if (input.value !== text && document.activeElement !== input) input.value = text;
        }),
      );
    },
  };
}
