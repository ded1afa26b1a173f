/**
 * Where presenter view puts a step's figures, without a browser: the
 * lesson's layout tree (rows, columns, grids) shared out over the
 * projector's figure area as the page's flex boxes share it. A row splits
 * its width by weights, a column its height, after any strip of fixed
 * height has taken its own; a grid splits both evenly. Figures the step
 * hides take no room, and neither does a row or column left empty.
 */
import { holdsShown, layoutTree } from './handout/frameLayout';
import type { LayoutNode } from './lesson';

export interface Placed {
  width: number;
  height: number;
}

interface Leaf {
  id: string;
  weight?: number;
  height?: number;
}

/** The gap between figures in a row or column (0.5rem). */
const GAP = 8;

export function presenterSizes(
  layout: 'row' | 'column' | LayoutNode | undefined,
  figures: readonly Leaf[],
  area: Placed,
  stripScale: number,
): Map<string, Placed> {
  const byId = new Map(figures.map((f) => [f.id, f]));
  const root = layoutTree(
    layout,
    figures.map((f) => f.id),
  );
  const sizes = new Map<string, Placed>();
  const shown = new Set(byId.keys());
  const shows = (node: LayoutNode) => holdsShown(node, shown);
  /** A strip's fixed height, or null for a figure (or box) that grows. */
  const fixed = (node: LayoutNode): number | null => {
    const height = typeof node === 'string' ? byId.get(node)?.height : undefined;
    return height ? Math.round(height * stripScale) : null;
  };
  const place = (node: LayoutNode, width: number, height: number): void => {
    if (typeof node === 'string') {
      sizes.set(node, { width, height: fixed(node) ?? height });
      return;
    }
    if ('grid' in node) {
      const { columns, rows, cells } = node.grid;
      const [w, h] = [
        (width - GAP * (columns.length - 1)) / columns.length,
        (height - GAP * (rows.length - 1)) / rows.length,
      ];
      for (const id of cells.flat()) if (byId.has(id)) place(id, w, h);
      return;
    }
    const along = 'row' in node;
    const all = along ? node.row : node.column;
    const kept = all.map((child, i) => ({ child, i })).filter(({ child }) => shows(child));
    const weightOf = ({ child, i }: { child: LayoutNode; i: number }) =>
      node.weights?.[i] ?? (typeof child === 'string' ? (byId.get(child)?.weight ?? 1) : 1);
    const space = (along ? width : height) - GAP * (kept.length - 1);
    const strips = along ? 0 : kept.reduce((sum, { child }) => sum + (fixed(child) ?? 0), 0);
    const growing = kept.filter(({ child }) => along || fixed(child) === null);
    const total = growing.reduce((sum, k) => sum + weightOf(k), 0);
    for (const k of kept) {
      const share = along || fixed(k.child) === null ? ((space - strips) * weightOf(k)) / total : 0;
      if (along) place(k.child, share, height);
      else place(k.child, width, fixed(k.child) ?? share);
    }
  };
  place(root, area.width, area.height);
  return sizes;
}

/**
 * The same tree as a phone stacks it: every row turned into a column (one
 * figure under another, each the screen's width), weights kept.
 */
export function stacked(
  layout: 'row' | 'column' | LayoutNode | undefined,
  ids: readonly string[],
): LayoutNode {
  if (layout === undefined || layout === 'row' || layout === 'column') return { column: [...ids] };
  const turn = (node: LayoutNode): LayoutNode =>
    typeof node === 'string' || 'grid' in node
      ? node
      : { column: ('row' in node ? node.row : node.column).map(turn), weights: node.weights };
  return turn(layout);
}
