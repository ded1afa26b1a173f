import type { KitFigure } from '../../kit/lesson';
import { boundsOf } from '../../render/projection';
import { DATASETS, type Dataset } from './model';
import type { BezierSplinesModel } from './model';
import { datasetPoints } from './points';
import type { GridReveal } from './script';
import type { BezierSplinesState } from './state';

// The practical's 3 × 3 figure: one small figure per dataset and continuity.
// Every cell of a row draws the same points, so dragging one in any cell
// moves it in the whole row.

/** Each dataset's row heading, and its cells' id (its key in the link). */
export const DATASET_TITLES: Record<Dataset, string> = {
  infinity: 'infinity',
  spiral: 'spiral',
  semicircle: 'semi',
};
const DATASET_IDS: Record<Dataset, string> = { infinity: 'inf', spiral: 'spi', semicircle: 'semi' };
/** The columns, each revealed by the step of its name. */
export const ORDERS = ['c0', 'c1', 'c2'] as const satisfies readonly GridReveal[];
type Order = (typeof ORDERS)[number];
const ORDER_TITLES: Record<Order, string> = { c0: 'C⁰', c1: 'C¹', c2: 'C²' };

export const cellId = (dataset: Dataset, order: Order) => `${DATASET_IDS[dataset]}-${order}`;

function cell(
  dataset: Dataset,
  order: Order,
  column: number,
): KitFigure<BezierSplinesState, BezierSplinesModel> {
  return {
    id: cellId(dataset, order),
    title: `${DATASET_TITLES[dataset]} as a ${ORDER_TITLES[order]} spline`,
    kind: 'geometry',
    bounds: (m) => boundsOf(m.grid[dataset].points),
    draw(painter, m) {
      const row = m.grid[dataset];
      for (const q of row.points) painter.dot(q, painter.theme.ink);
      if (m.shown.has(order))
        painter.cubicSegments(row[order], { role: 'curve', color: painter.color(column) });
    },
    points: [datasetPoints[dataset]],
  };
}

export const gridFigures = DATASETS.flatMap((dataset) =>
  ORDERS.map((order, c) => cell(dataset, order, c)),
);

/** The ids of the grid's nine cells: what the grid scene shows. */
export const gridFigureIds = gridFigures.map((f) => f.id);

export const gridLayout = {
  grid: {
    columns: ORDERS.map((o) => ORDER_TITLES[o]),
    rows: DATASETS.map((d) => DATASET_TITLES[d]),
    cells: DATASETS.map((d) => ORDERS.map((o) => cellId(d, o))),
  },
};
