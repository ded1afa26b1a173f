import { dataTable, fmt, h, liveText, setAttr, setChildren, setText } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { texT, words } from '../../kit/format';
import { LiveFormula } from '../../render/formula';
import { highlightedIndex, weightIds } from './hover';
import type { BlendingModel } from './model';
import type { BlendingState } from './state';
import { pointFormula, weightText } from './tex';

/**
 * The weights at μ: one row per control point (its W(N, i, μ) worked out),
 * the bar they fill together, their sum, and the point they make.
 */
export function weightsSection(api: LessonApi<BlendingState, BlendingModel>) {
  const title = liveText(h('h2', {}));
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  const bar = h('div', {
    class: 'partition-bar',
    role: 'img',
    style:
      'display:flex;height:1.6em;border:1px solid var(--line);border-radius:4px;overflow:hidden;margin:0.5em 0;contain:strict',
  });
  let pieces: HTMLElement[] = [];
  const sum = h('p', {});
  const point = new LiveFormula(true);
  let lit: number | null = null;

  // Hovering a row highlights its control point in both figures.
  body.addEventListener('mouseover', (e) => {
    const row = (e.target as Element).closest('tr');
    if (row) api.setHover(weightIds.id(row.sectionRowIndex));
  });
  body.addEventListener('mouseleave', () => api.setHover(null));

  function showLit() {
    [...body.rows].forEach((row, i) => row.classList.toggle('current', i === lit));
    pieces.forEach((piece, i) => {
      const outline = i === lit ? '3px solid var(--ink)' : '';
      if (piece.style.outline === outline) return;
      piece.style.outline = outline;
      piece.style.outlineOffset = outline ? '-3px' : '';
    });
  }

  return {
    elements: [
      title,
      dataTable('Weights at μ', ['Point', 'W(N, i, μ)', 'Weight'], body, 'expressions'),
      bar,
      sum,
      point.element,
    ],
    update(m: BlendingModel) {
      const { n, weights } = m;
      const { mu, p } = m.state;
      const palette = api.theme().palette;
      const color = (i: number) => palette[i % palette.length];
      setText(title, `Weights at μ = ${texT(mu)} (N = ${n})`);
      rows.set(
        weights.map((w, i) => ({
          cells: [{ text: `P${i}`, swatch: color(i) }, weightText(n, i, mu), fmt(w, 6)],
          data: { value: String(w) },
          // The hovered point's row stays lit: setting its class anew would restyle the table each frame.
          className: i === lit ? 'current' : undefined,
        })),
      );

      if (pieces.length !== weights.length) {
        pieces = weights.map(() => h('span', {}));
        setChildren(bar, pieces);
      }
      weights.forEach((w, i) => {
        pieces[i].title = `W(${n}, ${i}, μ) = ${fmt(w, 4)}`;
        pieces[i].style.width = `${(100 * w).toFixed(3)}%`;
        pieces[i].style.background = color(i);
      });
      setAttr(
        bar,
        'aria-label',
        `The weights stacked: ${weights.map((w, i) => `P${i} ${fmt(100 * w, 1)}%`).join(', ')}`,
      );
      showLit();
      setText(
        sum,
        `Together they fill the bar: ΣW = ${words(m.sum)}. The weights are never negative and always sum to 1 (a partition of unity), so P(μ) is a convex combination of the control points and stays in their convex hull.`,
      );
      point.set(pointFormula(mu, weights, p, m.point, true));
    },
    hover(id: string | null) {
      lit = highlightedIndex(id);
      showLit();
    },
  };
}
