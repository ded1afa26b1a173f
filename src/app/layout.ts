/**
 * Puts a lesson's figures on the page: all in a row or a column, or a tree of
 * rows, columns and grids with headings (Observable Plot's facets: one scale
 * and one heading for a row or column of figures).
 */
import { h, setHidden } from './dom';
import type { LayoutNode } from './lesson';

export function buildLayout(
  layout: 'row' | 'column' | LayoutNode | undefined,
  figures: ReadonlyMap<string, HTMLElement>,
): HTMLElement {
  if (layout === undefined || layout === 'row' || layout === 'column') {
    return h('div', { class: `figures layout-${layout ?? 'row'}` }, ...figures.values());
  }
  const root = node(layout, figures);
  return root.classList.contains('figures')
    ? root
    : h('div', { class: 'figures layout-row' }, root);
}

function node(layout: LayoutNode, figures: ReadonlyMap<string, HTMLElement>): HTMLElement {
  if (typeof layout === 'string') {
    const figure = figures.get(layout);
    if (!figure) throw new Error(`The layout names a figure "${layout}" the lesson does not have`);
    return figure;
  }
  if ('grid' in layout) {
    const { columns, rows, cells } = layout.grid;
    const grid = h('div', {
      class: 'figures figure-grid',
      style: `grid-template-columns: auto repeat(${columns.length}, minmax(0, 1fr)); grid-template-rows: auto repeat(${rows.length}, minmax(160px, 1fr))`,
    });
    grid.append(h('div', { class: 'grid-corner' }));
    for (const title of columns)
      grid.append(h('div', { class: 'grid-heading grid-column' }, title));
    rows.forEach((title, r) => {
      grid.append(h('div', { class: 'grid-heading grid-row' }, title));
      for (const id of cells[r] ?? []) grid.append(node(id, figures));
    });
    return grid;
  }
  const children = 'row' in layout ? layout.row : layout.column;
  const box = h('div', { class: `figures layout-${'row' in layout ? 'row' : 'column'}` });
  children.forEach((child, i) => {
    const el = node(child, figures);
    const weight = layout.weights?.[i];
    if (weight !== undefined) el.style.flexGrow = String(weight);
    box.append(el);
  });
  return box;
}

/**
 * Shows the figures a scene declares (`ids`, or all for null) and hides the
 * others, with any row, column or grid of the layout left with no figure to show.
 */
export function showFigures(
  box: HTMLElement,
  figures: readonly { readonly element: HTMLElement; readonly spec: { readonly id: string } }[],
  ids: readonly string[] | null,
): void {
  for (const figure of figures)
    setHidden(figure.element, ids !== null && !ids.includes(figure.spec.id));
  const groups = [...box.querySelectorAll<HTMLElement>('.figures')].reverse();
  for (const group of groups)
    setHidden(
      group,
      ![...group.children].some(
        (child) =>
          child instanceof HTMLElement &&
          !child.hidden &&
          !child.matches('.grid-heading, .grid-corner'),
      ),
    );
}
