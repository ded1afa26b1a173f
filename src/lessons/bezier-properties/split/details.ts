import { dataTable, h, setText } from '../../../app/dom';
import { LiveRows } from '../../../app/liveTable';
import { LiveFormula } from '../../../render/formula';
import { sub, texT } from '../../../kit/format';
import { type ExperimentPanel, arrangements, coords, slotPoint } from '../experimentPanel';
import type { ModelOf } from '../model';

/** `\text{left: } (x, y), (x, y), …` with one point slot per control point. */
const polygonShape = (name: string, count: number) =>
  `\\text{${name}: } ${Array.from({ length: count }, () => slotPoint()).join(',\\ ')}`;

export const splitPanel: ExperimentPanel<ModelOf<'split'>> = {
  number: 6,
  title: 'Subdivision',
  sentence:
    'De Casteljau at t splits the curve into two Bézier curves with their own control polygons; split the pieces again and again and the polygons converge to the curve, fast.',
  build() {
    const atEnd = h('p', {});
    const unsplit = h(
      'p',
      {},
      'Not split yet. Press "Split every piece" (or step forward); t sets where.',
    );
    const firstSplit = h('p', {});
    const left = new LiveFormula(true);
    const right = new LiveFormula(true);
    const body = h('tbody', {});
    const rows = new LiveRows(body);
    const table = dataTable(
      'Subdivision levels',
      ['Splits', 'Pieces', 'Largest polygon gap'],
      body,
    );
    const note = h(
      'p',
      { class: 'note' },
      'At t = 0.5 each split divides the gap between polygon and curve by about 4: far faster than raising the degree. This is how curves are drawn and intersected in practice.',
    );
    const show = arrangements();
    return {
      update(m) {
        const { t } = m.state;
        const splits = m.levels.length - 1;
        const n = m.controls.length - 1;
        setText(
          atEnd,
          `At t = ${t} one of the two pieces is the single point P${t === 0 ? '0' : `${n}`} and the other is the whole curve again: nothing is gained. Choose t inside (0, 1).`,
        );
        if (m.first) {
          setText(
            firstSplit,
            `First split at t = ${texT(t)}: the left polygon is the first point of every level of de Casteljau’s construction (from P${sub(0)} to P(t)), the right one the last point of every level (from P(t) to P${sub(n)}).`,
          );
          left.set(
            polygonShape('left', m.first[0].length),
            m.first[0].flatMap((q) => coords(q)),
          );
          right.set(
            polygonShape('right', m.first[1].length),
            m.first[1].flatMap((q) => coords(q)),
          );
        }
        rows.set(
          m.gaps.map((gap, j) => ({
            className: j === splits ? 'current' : '',
            cells: [String(j), String(m.levels[j].length), gap.toFixed(5)],
          })),
        );
        return show(`${m.atEnd} ${m.first !== null}`, () => [
          ...(m.atEnd ? [atEnd] : []),
          ...(m.first ? [firstSplit, left.element, right.element] : [unsplit]),
          table,
          note,
        ]);
      },
    };
  },
};
