import { dataTable, h, setClass, setHidden, setText } from '../../app/dom';
import { LiveRows } from '../../app/liveTable';
import { pointWords, sub, words } from '../../kit/format';
import type { DeCasteljauModel } from './model';
import { LECTURE_PSEUDOCODE, notesSymbols, recursionSlip } from './notes';
import { LINES_RUN, LISTING, PLOT_STEPS } from './pseudocode';

const nameWords = (r: number, i: number) => `P${sub(r)},${sub(i)}`;

/** What each line of the listing holds now: its loop variable, the point it made. */
export function lineValues(m: DeCasteljauModel): string[] {
  const { shown, current, n, levels, state } = m;
  const values = LISTING.map(() => '');
  values[0] = `n = ${n}, t = ${words(state.t)}`;
  if (shown.has('copy')) values[1] = `${nameWords(0, 0)} … ${nameWords(0, n)}`;
  if (current.length > 0) {
    const [r, i] = current[0];
    const last = current[current.length - 1][1];
    values[2] = `r = ${r}`;
    values[3] = current.length > 1 ? `i = 0 … ${last}` : `i = ${i}`;
    values[4] =
      current.length > 1
        ? `${nameWords(r, 0)} … ${nameWords(r, last)}`
        : `${nameWords(r, i)} = ${pointWords(levels[r][i])}`;
  } else if (shown.has('return')) values[2] = `r = 1 … ${n} done`;
  if (shown.has('return')) values[5] = `${nameWords(n, 0)} = ${pointWords(levels[n][0])}`;
  if (shown.has('plot')) values[6] = `L = ${PLOT_STEPS}: ${PLOT_STEPS + 1} points`;
  return values;
}

/** The listing, the line each step runs marked, with the lecture notes' own recursive version. */
function pseudocodeSection() {
  // What a line holds now sits under the line, not in a third column: a
  // laptop's 404 px panel had the values 230 px to the right of its edge.
  const rows = LISTING.map(([line, text]) => {
    const now = h('div', { class: 'now' });
    const row = h(
      'tr',
      {},
      h('td', {}, String(line)),
      h('td', {}, h('div', { class: 'code' }, text), now),
    );
    return { row, now };
  });
  const element = h(
    'div',
    {},
    h('h2', {}, 'The construction as pseudocode'),
    h(
      'p',
      {},
      'Two loops fill the levels: line 4 makes one point each time it runs. Each step runs the marked line with the figure’s numbers; the table of constructed points below lists every one of them.',
    ),
    h(
      'p',
      { class: 'note' },
      'Run at t = 0.5 on a cubic, it answers the lecture slides’ Example 4.18, “Where is x(0.5)?”, by hand: every intermediate point, then the point. (The “Splines” slides point to a worked example outside the notes.)',
    ),
    dataTable(
      'Pseudocode of the de Casteljau construction',
      ['Line', 'Pseudocode, and what it holds now'],
      h('tbody', {}, ...rows.map(({ row }) => row)),
      'listing',
    ),
    h(
      'p',
      {},
      'The lecture notes write it as a recursive function, with a drawCurve that plots it:',
    ),
    // As the notes write it, line for line; a line longer than the panel
    // (casteljau's recursive call: 831 px in a laptop's 404) goes on under
    // itself, indented further, as a listing is printed on a narrow page.
    h(
      'pre',
      { 'aria-label': 'The lecture notes’ pseudocode', class: 'quoted-code' },
      ...LECTURE_PSEUDOCODE.split('\n').map((line) => {
        const code = line.trimStart();
        return h('span', { style: `--indent:${line.length - code.length}ch` }, code);
      }),
    ),
    recursionSlip(),
    notesSymbols(),
  );
  return {
    element,
    update(m: DeCasteljauModel) {
      const run =
        m.shown.name in LINES_RUN ? LINES_RUN[m.shown.name as keyof typeof LINES_RUN] : [];
      const values = lineValues(m);
      rows.forEach(({ row, now }, k) => {
        const className = run.includes(LISTING[k][0]) ? 'current' : '';
        if (row.className !== className) setClass(row, className);
        setText(now, values[k] && `→ ${values[k]}`);
      });
    },
  };
}

/** Each level's weights W(r, 0, t) … W(r, r, t) and its first point, up to the level shown. */
function bernsteinSection() {
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  const element = h(
    'div',
    {},
    h('h2', {}, 'Level by level in the control points'),
    h(
      'p',
      {},
      'Each point of level r blends r + 1 neighbouring control points with the Bernstein weights: Pᵣ,ᵢ = Σⱼ W(r, j, t) Pᵢ₊ⱼ, whose weights are never negative and add up to 1. The lecture notes (“The de Casteljau form”) expand the recursion backwards from P₃,₀; here it is built forwards, level by level, and the sums are the same.',
    ),
    dataTable(
      'Weights of each level',
      // Each W(…) whole on its line (no-break spaces): the heading breaks at the dots.
      ['Level r', 'W(r,\u00A00,\u00A0t) … W(r,\u00A0r,\u00A0t)', 'Pᵣ,₀'],
      body,
      'names lists',
    ),
    h(
      'p',
      { class: 'note' },
      'The lecture slides’ Example 4.18 asks where x(0.5) is on a cubic: at t = 0.5 the last row holds its weights.',
    ),
  );
  return {
    element,
    update(m: DeCasteljauModel) {
      rows.set(
        m.weights.slice(1).map((weights, k) => {
          const r = k + 1;
          const known = m.computed[r] > 0;
          return {
            className: m.current.some(([level]) => level === r) ? 'current' : known ? '' : 'future',
            cells: [
              String(r),
              known ? weights.map(words).join(', ') : '—',
              known ? pointWords(m.blends[r][0]) : '—',
            ],
          };
        }),
      );
    },
  };
}

/** The panel's part for the pseudocode and the expansion: shown only in those scenes. */
export function walkPanel() {
  const pseudocode = pseudocodeSection();
  const bernstein = bernsteinSection();
  return {
    elements: [pseudocode.element, bernstein.element],
    update(m: DeCasteljauModel) {
      const { mode } = m.state;
      setHidden(pseudocode.element, mode !== 'pseudocode');
      setHidden(bernstein.element, mode !== 'bernstein');
      if (mode === 'pseudocode') pseudocode.update(m);
      if (mode === 'bernstein') bernstein.update(m);
    },
  };
}
