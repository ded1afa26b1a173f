/**
 * Table rows updated in place: a panel's table keeps its row and cell
 * elements, and each frame writes only the texts, classes and swatch colours
 * that changed, instead of building the table again.
 */
import { subscriptNames } from '../kit/subscripts';
import { h, setClass, setIndexedText } from './dom';
import { HELD_CELL, boxIfNumber } from '../render/cellBoxes';
import { type Unseen, waitUnseen, watchSeen } from '../render/unseen';

export interface Cell {
  text: string;
  /** A colour key drawn before the text. */
  swatch?: string;
}

export interface RowSpec {
  cells: readonly (string | Cell)[];
  /** `current`, `future`, … (see the data-table styles). */
  className?: string;
  /** `data-*` attributes, e.g. `{ level: '2' }`. */
  data?: Readonly<Record<string, string>>;
  /** The first cell is a row heading (`th scope="row"`). */
  heading?: boolean;
}

interface LiveCell {
  element: HTMLTableCellElement;
  /** The cell's words, after its swatch: indices (D₀) in spans the style sheet sets larger. */
  text: HTMLSpanElement;
  swatch: HTMLElement | null;
  swatchColor: string;
}

interface LiveRow {
  element: HTMLTableRowElement;
  cells: LiveCell[];
  data: string;
}

export class LiveRows implements Unseen {
  private rows: LiveRow[] = [];
  /** The rows asked for last, written when the table comes into view (see unseen.ts). */
  private latest: readonly RowSpec[] = [];

  constructor(readonly body: HTMLTableSectionElement) {
    watchSeen(body, this);
  }

  catchUp(): void {
    this.set(this.latest);
  }

  set(specs: readonly RowSpec[]): void {
    this.latest = specs;
    // Out of view while a point is dragged: written when seen or let go.
    if (waitUnseen(this.body, this)) return;
    specs.forEach((spec, i) => {
      let row = this.rows[i];
      if (!row || row.cells.length !== spec.cells.length) {
        const fresh = this.create(spec);
        if (row) row.element.replaceWith(fresh.element);
        else this.body.append(fresh.element);
        this.rows[i] = row = fresh;
      }
      setClass(row.element, spec.className ?? '');
      const data = spec.data ? JSON.stringify(spec.data) : '';
      if (row.data !== data) {
        row.data = data;
        for (const [key, value] of Object.entries(spec.data ?? {}))
          row.element.dataset[key] = value;
      }
      spec.cells.forEach((cell, c) => this.fill(row.cells[c], cell));
    });
    for (const extra of this.rows.splice(specs.length)) extra.element.remove();
  }

  private create(spec: RowSpec): LiveRow {
    const cells: LiveCell[] = spec.cells.map((_, c) => {
      const element = h(
        spec.heading && c === 0 ? 'th' : 'td',
        spec.heading && c === 0 ? { scope: 'row' } : {},
      );
      // Its words are held in a box of their own through a drag (liveBoxes.ts' holdCells).
      const text = h('span', { [`data-${HELD_CELL}`]: '' });
      element.append(text);
      return { element, text, swatch: null, swatchColor: '' };
    });
    const element = h('tr', {}, ...cells.map((c) => c.element));
    return { element, cells, data: '' };
  }

  private fill(live: LiveCell, cell: string | Cell): void {
    const { text, swatch } = typeof cell === 'string' ? { text: cell, swatch: undefined } : cell;
    // A cell names points as the figure does (P₀, not P0): see dom.ts' PROSE.
    const shown = subscriptNames(text);
    // A lone number in a box of its own: a drag that changes it lays out the box (liveBoxes.ts).
    boxIfNumber(live.text, shown);
    setIndexedText(live.text, shown);
    if (swatch && !live.swatch) {
      live.swatch = h('span', { class: 'swatch' });
      live.element.prepend(live.swatch);
    }
    if (live.swatch) {
      if (!swatch) {
        live.swatch.remove();
        live.swatch = null;
        live.swatchColor = '';
      } else if (live.swatchColor !== swatch) {
        live.swatchColor = swatch;
        live.swatch.style.background = swatch;
      }
    }
  }
}
