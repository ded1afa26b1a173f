/**
 * A handout page's geometry in millimetres, and the size a frame's figure is
 * drawn at (CSS pixels at 96 per inch, so the figure's text prints at the
 * size the theme sets).
 */
import { GRID, type Paper, type PerPage } from './plan';

export const PX_PER_MM = 96 / 25.4;

const PAPER: Record<Paper, { width: number; height: number; css: string }> = {
  a4: { width: 210, height: 297, css: 'A4 portrait' },
  letter: { width: 215.9, height: 279.4, css: 'letter portrait' },
};

const MARGIN = 12;
/** The title block on the first page, the running head on the others. */
export const HEAD = 30;
export const FOOT = 7;
const GAP = 4;
/** A frame's heading line (scene and step). */
const FRAME_HEAD = 5;
/** Room for the caption and the formula under the figure. */
const TEXT: Record<PerPage, number> = { 1: 42, 2: 30, 4: 30, 6: 25 };
/** A table's title, heading row and body row. */
const TABLE_TITLE = 7;
const TABLE_ROW = 4.6;

export interface PageGeometry {
  paper: { width: number; height: number; css: string };
  margin: number;
  body: { width: number; height: number };
  cell: { width: number; height: number };
  gap: number;
  columns: number;
  rows: number;
  /** The figure's box in a frame (mm). */
  figure: { width: number; height: number };
  frameHead: number;
  text: number;
}

export function pageGeometry(paper: Paper, perPage: PerPage): PageGeometry {
  const sheet = PAPER[paper];
  const { columns, rows } = GRID[perPage];
  const body = {
    width: sheet.width - 2 * MARGIN,
    height: sheet.height - 2 * MARGIN - HEAD - FOOT,
  };
  const cell = {
    width: (body.width - GAP * (columns - 1)) / columns,
    height: (body.height - GAP * (rows - 1)) / rows,
  };
  return {
    paper: sheet,
    margin: MARGIN,
    body,
    cell,
    gap: GAP,
    columns,
    rows,
    figure: { width: cell.width, height: cell.height - FRAME_HEAD - TEXT[perPage] },
    frameHead: FRAME_HEAD,
    text: TEXT[perPage],
  };
}

/** Grid rows a table of `rows` body rows takes. */
export function tableRows(geometry: PageGeometry, rows: number): number {
  const height = TABLE_TITLE + TABLE_ROW * (rows + 1);
  return Math.ceil((height + geometry.gap) / (geometry.cell.height + geometry.gap));
}

/** The most body rows of a table that fit on one page (a longer table prints in parts). */
export function rowsPerPage(geometry: PageGeometry): number {
  return Math.max(1, Math.floor((geometry.body.height - TABLE_TITLE) / TABLE_ROW) - 1);
}
