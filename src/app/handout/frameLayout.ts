/**
 * Where a frame's figures go on paper: the lesson's own layout tree (rows,
 * columns, grids with headings, as on screen) cut into boxes of a given
 * size, with the figures a step hides left out and boxes they emptied closed.
 */
import type { FigureSpec, LayoutNode } from '../lesson';

export interface Box {
  x: number;
  y: number;
  w: number;
  h: number;
}

export interface Heading {
  text: string;
  box: Box;
}

export interface FrameLayout {
  /** Each shown figure's box, in the layout's order. */
  figures: { id: string; box: Box }[];
  /** Row and column headings of a grid. */
  headings: Heading[];
}

type Spec = Pick<FigureSpec<unknown>, 'id' | 'weight' | 'height'>;

/** Height and width of a grid's headings (px). */
const HEADING = 22;
const ROW_HEADING = 64;
/** A fixed-height strip (a knot line) takes at most this share of its column. */
const STRIP_SHARE = 0.22;

export function layoutFrame(
  layout: 'row' | 'column' | LayoutNode | undefined,
  specs: readonly Spec[],
  shown: ReadonlySet<string>,
  box: Box,
): FrameLayout {
  const out: FrameLayout = { figures: [], headings: [] };
  const byId = new Map(specs.map((s) => [s.id, s]));
  place(
    layoutTree(
      layout,
      specs.map((s) => s.id),
    ),
    box,
    byId,
    shown,
    out,
  );
  return out;
}

/** A lesson's layout as a tree: all its figures in a row (the default) or a column, or its own tree. */
export function layoutTree(
  layout: 'row' | 'column' | LayoutNode | undefined,
  ids: readonly string[],
): LayoutNode {
  return layout === undefined || layout === 'row'
    ? { row: [...ids] }
    : layout === 'column'
      ? { column: [...ids] }
      : layout;
}

/** Does the node hold a figure the step shows? */
export function holdsShown(node: LayoutNode, shown: ReadonlySet<string>): boolean {
  if (typeof node === 'string') return shown.has(node);
  if ('grid' in node) return node.grid.cells.flat().some((id) => shown.has(id));
  return ('row' in node ? node.row : node.column).some((child) => holdsShown(child, shown));
}

function place(
  node: LayoutNode,
  box: Box,
  byId: ReadonlyMap<string, Spec>,
  shown: ReadonlySet<string>,
  out: FrameLayout,
): void {
  if (typeof node === 'string') {
    if (shown.has(node)) out.figures.push({ id: node, box });
    return;
  }
  if ('grid' in node) {
    placeGrid(node.grid, box, shown, out);
    return;
  }
  const all = 'row' in node ? node.row : node.column;
  // Paper frames are nearly square: a row whose figures would each be much
  // taller than wide is stacked instead.
  const across =
    'row' in node &&
    box.w / Math.max(1, all.filter((c) => holdsShown(c, shown)).length) >= box.h * 0.6;
  const children = all
    .map((child, i) => ({ child, weight: node.weights?.[i] ?? leafWeight(child, byId) }))
    .filter(({ child }) => holdsShown(child, shown));
  if (children.length === 0) return;
  const length = across ? box.w : box.h;
  // A strip of fixed height keeps its height in a column (shrunk on a small frame).
  const fixed = children.map(({ child }) =>
    !across && typeof child === 'string' && byId.get(child)?.height !== undefined
      ? Math.min(byId.get(child)!.height!, length * STRIP_SHARE)
      : null,
  );
  const fixedTotal = fixed.reduce<number>((sum, f) => sum + (f ?? 0), 0);
  const weightTotal = children.reduce((sum, c, i) => sum + (fixed[i] === null ? c.weight : 0), 0);
  let at = across ? box.x : box.y;
  children.forEach(({ child, weight }, i) => {
    const size = fixed[i] ?? ((length - fixedTotal) * weight) / (weightTotal || 1);
    const part: Box = across
      ? { x: at, y: box.y, w: size, h: box.h }
      : { x: box.x, y: at, w: box.w, h: size };
    at += size;
    place(child, part, byId, shown, out);
  });
}

function leafWeight(node: LayoutNode, byId: ReadonlyMap<string, Spec>): number {
  return typeof node === 'string' ? (byId.get(node)?.weight ?? 1) : 1;
}

function placeGrid(
  grid: { columns: string[]; rows: string[]; cells: string[][] },
  box: Box,
  shown: ReadonlySet<string>,
  out: FrameLayout,
): void {
  const rows = grid.rows
    .map((title, r) => ({ title, cells: grid.cells[r] ?? [] }))
    .filter((row) => row.cells.some((id) => shown.has(id)));
  const columns = grid.columns
    .map((title, c) => ({ title, c }))
    .filter(({ c }) => rows.some((row) => shown.has(row.cells[c])));
  if (rows.length === 0 || columns.length === 0) return;
  const cellW = (box.w - ROW_HEADING) / columns.length;
  const cellH = (box.h - HEADING) / rows.length;
  columns.forEach(({ title }, j) =>
    out.headings.push({
      text: title,
      box: { x: box.x + ROW_HEADING + j * cellW, y: box.y, w: cellW, h: HEADING },
    }),
  );
  rows.forEach((row, i) => {
    const y = box.y + HEADING + i * cellH;
    out.headings.push({ text: row.title, box: { x: box.x, y, w: ROW_HEADING, h: cellH } });
    columns.forEach(({ c }, j) => {
      const id = row.cells[c];
      if (id !== undefined && shown.has(id))
        out.figures.push({
          id,
          box: { x: box.x + ROW_HEADING + j * cellW, y, w: cellW, h: cellH },
        });
    });
  });
}
