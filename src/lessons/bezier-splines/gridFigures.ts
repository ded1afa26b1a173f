import type { FigureSpec } from '../../app/lesson';
import { boundsOf } from '../../render/projection';
import { DATASETS, type Dataset } from './model';
import type { BezierSplinesModel } from './model';
import type { BezierSplinesState } from './state';

// The practical's 3 × 3 figure: one small figure per dataset and continuity.
// Every cell of a row draws the same points, so dragging one in any cell
// moves it in the whole row.

export const DATASET_TITLES: Record<Dataset, string> = {
  inf: 'infinity',
  spi: 'spiral',
  semi: 'semi',
};
export const ORDERS = ['c0', 'c1', 'c2'] as const;
type Order = (typeof ORDERS)[number];
const ORDER_TITLES: Record<Order, string> = { c0: 'C⁰', c1: 'C¹', c2: 'C²' };

export const cellId = (dataset: Dataset, order: Order) => `${dataset}-${order}`;

function cell(
  dataset: Dataset,
  order: Order,
  column: number,
): FigureSpec<BezierSplinesState, BezierSplinesModel> {
  return {
    id: cellId(dataset, order),
    title: `${DATASET_TITLES[dataset]} as a ${ORDER_TITLES[order]} spline`,
    kind: 'geometry',
    bounds: (m) => boundsOf(m.grid[dataset].points),
    draw(painter, m) {
      const row = m.grid[dataset];
      // Step k shows the first k columns' splines.
      for (const q of row.points) painter.dot(q, painter.theme.ink);
      if (m.state.step > column)
        painter.cubicSegments(row[order], { role: 'curve', color: painter.color(column) });
    },
    handles: (m) =>
      m.grid[dataset].points.map((position, i) => ({
        id: `p${i}`,
        label: `p_{${i}}`,
        position,
        small: true,
        showLabel: false,
      })),
    moveHandle(state, id, to) {
      const i = Number(id.slice(1));
      return { ...state, [dataset]: state[dataset].map((q, k) => (k === i ? [to[0], to[1]] : q)) };
    },
  };
}

export const gridFigures = DATASETS.flatMap((dataset) =>
  ORDERS.map((order, c) => cell(dataset, order, c)),
);

export const gridLayout = {
  grid: {
    columns: ORDERS.map((o) => ORDER_TITLES[o]),
    rows: DATASETS.map((d) => DATASET_TITLES[d]),
    cells: DATASETS.map((d) => ORDERS.map((o) => cellId(d, o))),
  },
};
