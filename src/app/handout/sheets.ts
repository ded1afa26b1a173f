/**
 * The handout's pages as DOM: one sheet per page at the paper's size, the
 * title block on the first, a running head and "page i of n" on every one,
 * and the frames and tables where `paginate` put them.
 */
import { formula } from '../../render/formula';
import { makePaperTheme } from '../../render/theme';
import { h } from '../dom';
import type { AnyLesson, HandoutTable } from '../lesson';
import type { LessonMeta } from '../meta';
import { frameSvg } from './frameSvg';
import { PX_PER_MM, type PageGeometry } from './geometry';
import type { FramePlan, Placed, TablePlan } from './plan';
import { qrCode } from './qr';

export interface SheetContext {
  meta: LessonMeta;
  lesson: AnyLesson;
  geometry: PageGeometry;
  views: Readonly<Record<string, string>>;
  /** The link to the lesson as shown. */
  link: string;
  date: Date;
}

const mm = (v: number) => `${Math.round(v * 100) / 100}mm`;

/** An SVG document made here (escaped text, no script) as a node of this page. */
export function svgNode(markup: string): Element {
  const doc = new DOMParser().parseFromString(markup, 'image/svg+xml');
  return document.importNode(doc.documentElement, true);
}

export function buildSheets(pages: readonly Placed[][], context: SheetContext): HTMLElement[] {
  const { geometry } = context;
  const theme = makePaperTheme();
  return pages.map((placed, i) => {
    const grid = h('div', {
      class: 'sheet-body',
      style: `grid-template-columns: repeat(${geometry.columns}, ${mm(geometry.cell.width)}); grid-template-rows: repeat(${geometry.rows}, ${mm(geometry.cell.height)}); gap: ${mm(geometry.gap)}`,
    });
    for (const { item, row, column, rowSpan } of placed) {
      const el = item.kind === 'frame' ? frameElement(item, context, theme) : tableElement(item);
      el.style.gridRow = `${row + 1} / span ${rowSpan}`;
      el.style.gridColumn = item.kind === 'frame' ? `${column + 1}` : '1 / -1';
      grid.append(el);
    }
    return h(
      'section',
      {
        class: 'sheet',
        'aria-label': `Page ${i + 1} of ${pages.length}`,
        style: `width: ${mm(geometry.paper.width)}; height: ${mm(geometry.paper.height)}; padding: ${mm(geometry.margin)}`,
      },
      i === 0 ? titleBlock(context) : runningHead(context),
      grid,
      h(
        'footer',
        { class: 'sheet-foot' },
        h('span', {}, `${context.meta.title} · Spline Lab`),
        h('span', { class: 'page-number' }, `Page ${i + 1} of ${pages.length}`),
      ),
    );
  });
}

function titleBlock({ meta, link, date }: SheetContext): HTMLElement {
  const printed = date.toLocaleDateString('en-GB', {
    day: 'numeric',
    month: 'long',
    year: 'numeric',
  });
  return h(
    'header',
    { class: 'sheet-head title-block' },
    h(
      'div',
      { class: 'title-text' },
      h('h1', {}, meta.title),
      h('p', { class: 'summary' }, meta.summary),
      h('p', { class: 'printed' }, `Spline Lab · ${printed}`),
      h('p', { class: 'link' }, h('a', { href: link }, link)),
    ),
    qrCode(link, 22),
  );
}

function runningHead({ meta }: SheetContext): HTMLElement {
  return h('header', { class: 'sheet-head running-head' }, meta.title);
}

function frameElement(
  frame: FramePlan,
  context: SheetContext,
  theme: ReturnType<typeof makePaperTheme>,
): HTMLElement {
  const { geometry } = context;
  const width = geometry.figure.width * PX_PER_MM;
  const height = geometry.figure.height * PX_PER_MM;
  const svg = svgNode(
    frameSvg(context.lesson, frame.state, frame.figures, width, height, theme, context.views),
  );
  svg.setAttribute('width', mm(geometry.figure.width));
  svg.setAttribute('height', mm(geometry.figure.height));
  return h(
    'figure',
    {
      class: 'frame',
      'data-scene': frame.scene.id,
      'data-step': frame.step,
    },
    h(
      'p',
      { class: 'frame-head', style: `height: ${mm(geometry.frameHead)}` },
      `${frame.scene.label} · step ${frame.step}/${frame.last}`,
    ),
    svg,
    h(
      'figcaption',
      { class: 'frame-text', style: `height: ${mm(geometry.text)}` },
      h('p', { class: 'frame-caption' }, frame.caption),
      frame.formula
        ? h('p', { class: 'frame-formula' }, formula(`\\displaystyle ${frame.formula}`))
        : null,
    ),
  );
}

function tableElement(item: TablePlan): HTMLElement {
  const table: HandoutTable = item.table;
  const title =
    item.parts > 1 ? `${table.title} (part ${item.part + 1} of ${item.parts})` : table.title;
  return h(
    'div',
    { class: 'handout-table', 'data-scene': item.scene.id },
    h(
      'table',
      {},
      h('caption', {}, `${item.scene.label}: ${title}`),
      h(
        'thead',
        {},
        h(
          'tr',
          {},
          table.columns.map((c) => h('th', { scope: 'col' }, c)),
        ),
      ),
      h(
        'tbody',
        {},
        table.rows.map((row) =>
          h(
            'tr',
            {},
            row.map((cell) => h('td', {}, cell)),
          ),
        ),
      ),
    ),
  );
}

/**
 * Shrinks each frame's formula until it fits the room under the figure and
 * its caption (inline, so a long one breaks after its relations first): one
 * pass of reads, then one of writes, until all fit, never below 40 %.
 */
export function fitFrameText(root: ParentNode): void {
  for (let pass = 0; pass < 8; pass++) {
    const boxes = [...root.querySelectorAll<HTMLElement>('.frame-text')];
    const fits = boxes.map((box) => {
      const formula = box.querySelector<HTMLElement>('.frame-formula');
      if (!formula) return null;
      const caption = box.querySelector<HTMLElement>('.frame-caption');
      const room = box.clientHeight - (caption?.offsetHeight ?? 0) - 4;
      const current = Number(formula.dataset.scale ?? '1');
      // KaTeX's lines are its .base boxes (scrollWidth also counts struts no one sees).
      const left = formula.getBoundingClientRect().left;
      const right = Math.max(
        0,
        ...[...formula.querySelectorAll('.katex-html > .base')].map(
          (base) => base.getBoundingClientRect().right - left,
        ),
      );
      const over = Math.max(formula.scrollHeight / Math.max(room, 1), right / formula.clientWidth);
      if (over <= 1.001) return null;
      return { formula, scale: Math.max(0.4, (current / over) * 0.95) };
    });
    if (fits.every((fit) => fit === null || fit.scale === Number(fit.formula.dataset.scale)))
      return;
    for (const fit of fits) {
      if (!fit) continue;
      fit.formula.dataset.scale = String(fit.scale);
      fit.formula.style.fontSize = `${fit.scale}em`;
    }
  }
}
