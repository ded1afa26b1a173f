import { trimmed } from '../../kit/format';
import type { KitFigure } from '../../kit/lesson';
import { labelWidth } from '../../render/labelWidth';
import type { SurfaceModel } from './model';
import type { SurfaceState } from './state';

// The 16 weights fm(u)·fn(v) at the cursor as a 4 × 4 heat map: cell (m, n)
// at column n, row m from the top, its colour as strong as its weight; the
// row factors fm(u) on the right, the column factors fn(v) below.

/** What the map shows at the step: the row factors, the column factors, or the products. */
export function weightsShown({ shown }: SurfaceModel): 'rows' | 'columns' | 'products' {
  if (shown.is('rowShares')) return 'rows';
  if (shown.is('columnShares')) return 'columns';
  return 'products';
}

const cell = (m: number, n: number) => [
  [n, 3 - m],
  [n + 1, 3 - m],
  [n + 1, 4 - m],
  [n, 4 - m],
];

export const weightsFigure: KitFigure<SurfaceState, SurfaceModel> = {
  id: 'weights',
  title: 'The 16 weights fm(u)·fn(v) at the point, as a heat map',
  kind: 'drawing',
  weight: 1,
  // On a phone the box is short and wide: cells half again as wide as tall
  // hold the numbers that square cells of its height could not.
  widen: 1.8,
  // Its bounds hold its factors and sum round the map, and it has no handles:
  // at a 1366 × 768 projector the default room left 80 px cells, too small
  // for the numbers at the least size, and the map showed none.
  edgeRoom: 0,
  bounds: () => ({ minX: -0.8, minY: -1.35, maxX: 5.2, maxY: 4.7 }),
  // fm(u)·fn(v) depend on (u, v) alone: a control point's drag does not draw the map again.
  drawnFrom: (m) => [m.state.u, m.state.v, m.shown.key],
  draw(painter, m, info) {
    const theme = painter.theme;
    const shown = weightsShown(m);
    const fu = m.rowShares;
    const fv = m.columnShares;
    // Numbers fit their cells: as large as the theme asks, or as the cell
    // allows (its widest number, "0.000", measured, in 0.85 of its width; a
    // line and a half up). Reckoned as five characters at 0.27 of the cell,
    // a 1366 × 768 projector's 88 px cells got 23.8 px numbers, under the
    // least size, and the map showed no number at all: "0.000" at 25 px is 71 px.
    const [x0, y0] = painter.view.toScreen([0, 0]);
    const [x1, y1] = painter.view.toScreen([1, 1]);
    const widest = labelWidth(painter, '0.000', { size: theme.sizes.label });
    const size = Math.min(
      theme.sizes.label,
      (theme.sizes.label * 0.85 * Math.abs(x1 - x0)) / widest,
      Math.abs(y1 - y0) * 0.45,
    );
    // Numbers are set at the theme's least size at smallest, which a cell
    // room for 0.85 of it still holds (a phone's map, 197 px tall: 11.1 px of
    // room for 12 px numbers). Cells smaller (the map squeezed under two
    // notices) show the weights by colour alone, the panel's table writing
    // them out: numbers pushed out of their cells no longer say whose they are.
    const legible = size >= 0.85 * (theme.sizes.minText ?? 0);
    const text = (t: string, x: number, y: number, color = theme.ink, bold = false) => {
      if (legible)
        // A table's entry stays at its row and column (moved aside, f₁(v)
        // stood under column 2 and f₃(v) off the map): the size fits them.
        painter.label(t, [x, y], {
          align: 'center',
          baseline: 'middle',
          color,
          size,
          bold,
          stays: true,
        });
    };
    for (let i = 0; i < 4; i++) {
      for (let j = 0; j < 4; j++) {
        const w = shown === 'rows' ? fu[i] : shown === 'columns' ? fv[j] : m.weights[i][j];
        // Alpha follows the weight on a square-root scale, so small weights still show.
        painter.polygon(cell(i, j), theme.accent, 0.06 + 0.94 * Math.sqrt(w), {
          color: theme.polygon,
          width: theme.sizes.thin,
        });
        if (!info.thumbnail) text(w.toFixed(shown === 'products' ? 3 : 2), j + 0.5, 3.5 - i);
      }
    }
    if (info.thumbnail) return;
    // The factors in their colours, not bold: bold, four in a row under the
    // map ran together ("0.0640.288…") at the size the cells allow.
    for (let i = 0; i < 4; i++) {
      text(`${i}`, -0.3, 3.5 - i, theme.muted);
      text(`${i}`, i + 0.5, 4.35, theme.muted);
      if (shown !== 'columns') text(fu[i].toFixed(3), 4.65, 3.5 - i, painter.color(0));
      if (shown !== 'rows') text(fv[i].toFixed(3), i + 0.5, -0.35, painter.color(1));
    }
    if (shown !== 'columns') text('f_m(u)', 4.65, 4.35, painter.color(0));
    if (shown !== 'rows') text('f_n(v)', -0.42, -0.35, painter.color(1));
    text('m∖n', -0.3, 4.35, theme.muted);
    if (shown === 'products') text(`Σ = ${trimmed(m.weightSum, 12)}`, 2, -1.05, theme.ink, true);
  },
};
