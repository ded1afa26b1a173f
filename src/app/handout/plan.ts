/**
 * What a handout prints, before any page exists: its options (kept in the
 * link beside the lesson's own state), the frames (a scene's steps, each a
 * state with its caption and formula), the tables under a scene's last frame,
 * and how they fall onto pages so that no frame is cut by a page's edge.
 */
import type { AnyLesson, HandoutTable } from '../lesson';
import { normalizeState } from '../lessonState';
import { defaultsOf } from '../urlState';

export type StepChoice = 'all' | 'last';
export type PerPage = 1 | 2 | 4 | 6;
export type Paper = 'a4' | 'letter';
export type Values = 'now' | 'own';

export interface HandoutOptions {
  /** Scene ids to print, in the lesson's order; empty means all of them. */
  scenes: string[];
  steps: StepChoice;
  perPage: PerPage;
  paper: Paper;
  values: Values;
}

export const DEFAULT_OPTIONS: HandoutOptions = {
  scenes: [],
  steps: 'all',
  perPage: 4,
  paper: 'a4',
  values: 'now',
};

/** The link keys of the options: prefixed, so they never meet a lesson's own keys. */
export const OPTION_KEYS = {
  scenes: 'handout.scenes',
  steps: 'handout.steps',
  perPage: 'handout.per-page',
  paper: 'handout.paper',
  values: 'handout.values',
} as const;

const PER_PAGE: readonly PerPage[] = [1, 2, 4, 6];

/** The options a link names, what it got wrong in words, and the lesson's own query without them. */
export function readOptions(
  query: string,
  sceneIds: readonly string[],
): { options: HandoutOptions; issues: string[]; lessonQuery: string } {
  // The lesson's own parts are kept exactly as written (its links keep `,` and `;` raw).
  const parts = query.split('&').filter((part) => part !== '');
  const own = (part: string) => !part.startsWith('handout.');
  const params = new URLSearchParams(parts.filter((part) => !own(part)).join('&'));
  const options: HandoutOptions = { ...DEFAULT_OPTIONS, scenes: [] };
  const issues: string[] = [];
  const take = (key: string) => {
    const value = params.get(key);
    params.delete(key);
    return value;
  };
  const steps = take(OPTION_KEYS.steps);
  if (steps === 'all' || steps === 'last') options.steps = steps;
  else if (steps !== null)
    issues.push(`Steps “${steps.slice(0, 20)}” is not “all” or “last”: every step is printed.`);
  const per = take(OPTION_KEYS.perPage);
  if (per !== null) {
    const n = Number(per) as PerPage;
    if (PER_PAGE.includes(n)) options.perPage = n;
    else
      issues.push(
        `${per.slice(0, 20)} frames a page is not offered (1, 2, 4 or 6): 4 are printed.`,
      );
  }
  const paper = take(OPTION_KEYS.paper);
  if (paper === 'a4' || paper === 'letter') options.paper = paper;
  else if (paper !== null)
    issues.push(`Paper “${paper.slice(0, 20)}” is not A4 or Letter: A4 is used.`);
  const values = take(OPTION_KEYS.values);
  if (values === 'now' || values === 'own') options.values = values;
  else if (values !== null)
    issues.push(
      `Values “${values.slice(0, 20)}” is not “now” or “own”: the values on screen are used.`,
    );
  const scenes = take(OPTION_KEYS.scenes);
  if (scenes !== null && scenes !== '') {
    const named = scenes.split(',');
    const unknown = named.filter((id) => !sceneIds.includes(id));
    if (unknown.length > 0)
      issues.push(
        `No scene called ${unknown.map((id) => `“${id.slice(0, 30)}”`).join(', ')}: left out.`,
      );
    options.scenes = sceneIds.filter((id) => named.includes(id));
  }
  for (const key of new Set(params.keys()))
    issues.push(`The handout has no option “${key.slice(0, 40)}”: left out.`);
  return { options, issues, lessonQuery: parts.filter(own).join('&') };
}

/** The options as link parameters: only those that differ from the defaults. */
export function writeOptions(options: HandoutOptions): string {
  const params = new URLSearchParams();
  if (options.scenes.length > 0) params.set(OPTION_KEYS.scenes, options.scenes.join(','));
  if (options.steps !== DEFAULT_OPTIONS.steps) params.set(OPTION_KEYS.steps, options.steps);
  if (options.perPage !== DEFAULT_OPTIONS.perPage)
    params.set(OPTION_KEYS.perPage, String(options.perPage));
  if (options.paper !== DEFAULT_OPTIONS.paper) params.set(OPTION_KEYS.paper, options.paper);
  if (options.values !== DEFAULT_OPTIONS.values) params.set(OPTION_KEYS.values, options.values);
  return params.toString().replaceAll('%2C', ',');
}

export interface SceneRef {
  id: string;
  label: string;
  index: number;
}

export interface FramePlan {
  kind: 'frame';
  scene: SceneRef;
  step: number;
  /** The scene's last step. */
  last: number;
  state: unknown;
  caption: string;
  formula: string | null;
  /** The figures this step shows, by id. */
  figures: string[];
}

export interface TablePlan {
  kind: 'table';
  scene: SceneRef;
  table: HandoutTable;
  /** A long table is printed in parts, each with its headings: which part (0 …) of how many. */
  part: number;
  parts: number;
}

export type Item = FramePlan | TablePlan;

/**
 * Each chosen scene's frames in teaching order, with its tables after its last frame.
 * `current` is the lesson's state now and `currentScene` the index of its scene.
 */
export function planItems(
  lesson: AnyLesson,
  current: unknown,
  currentScene: number,
  options: HandoutOptions,
): FramePlan[][] {
  const steps = lesson.steps;
  const scenes = lesson.scenes ?? [];
  const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
  const chosen = scenes
    .map((scene, index) => ({ id: scene.id, label: scene.label, index, apply: scene.apply }))
    .filter((scene) => options.scenes.length === 0 || options.scenes.includes(scene.id));
  return chosen.map((scene) => {
    const ref = { id: scene.id, label: scene.label, index: scene.index };
    const start =
      options.values === 'now' && scene.index === currentScene
        ? current
        : scene.apply(options.values === 'now' ? current : defaults);
    const withStep = (k: number) =>
      normalizeState(lesson, steps ? { ...(start as object), [steps.key]: k } : start).state;
    const last = steps ? steps.count(withStep(0)) : 0;
    const ks = options.steps === 'last' ? [last] : Array.from({ length: last + 1 }, (_, k) => k);
    return ks.map((k): FramePlan => {
      const state = withStep(k);
      const model = lesson.derive(state);
      const shown = lesson.figuresShown?.(state) ?? null;
      return {
        kind: 'frame',
        scene: ref,
        step: k,
        last,
        state,
        caption: steps ? steps.describe(state, k) : '',
        formula: steps?.formula?.(model, state) ?? null,
        figures: lesson.figures
          .map((f) => f.id)
          .filter((id) => shown === null || shown.includes(id)),
      };
    });
  });
}

/** The tables of a scene, under its last frame, cut into parts that fit `rowsPerPart` rows. */
export function tablesOf(lesson: AnyLesson, frame: FramePlan, rowsPerPart: number): TablePlan[] {
  const tables = lesson.tables?.(lesson.derive(frame.state), frame.state) ?? [];
  return tables.flatMap((table) => {
    const parts = Math.max(1, Math.ceil(table.rows.length / rowsPerPart));
    return Array.from({ length: parts }, (_, part) => ({
      kind: 'table' as const,
      scene: frame.scene,
      part,
      parts,
      table: { ...table, rows: table.rows.slice(part * rowsPerPart, (part + 1) * rowsPerPart) },
    }));
  });
}

/** Rows and columns of frames on a page, for each choice of frames a page. */
export const GRID: Record<PerPage, { columns: number; rows: number }> = {
  1: { columns: 1, rows: 1 },
  2: { columns: 1, rows: 2 },
  4: { columns: 2, rows: 2 },
  6: { columns: 2, rows: 3 },
};

export interface Placed {
  item: Item;
  row: number;
  column: number;
  /** Rows of the page's grid it takes (a table spans the page's width). */
  rowSpan: number;
}

/**
 * Items onto pages: frames fill the grid in reading order; a table starts a
 * fresh row across the page and takes the rows its height needs. An item
 * never crosses a page's edge, and no page is left without an item.
 */
export function paginate(
  items: readonly Item[],
  perPage: PerPage,
  rowsOf: (table: TablePlan) => number,
): Placed[][] {
  const { columns, rows } = GRID[perPage];
  const pages: Placed[][] = [];
  let page: Placed[] = [];
  let row = 0;
  let column = 0;
  const newPage = () => {
    if (page.length > 0) pages.push(page);
    page = [];
    row = 0;
    column = 0;
  };
  for (const item of items) {
    if (item.kind === 'frame') {
      if (row >= rows) newPage();
      page.push({ item, row, column, rowSpan: 1 });
      column++;
      if (column === columns) {
        column = 0;
        row++;
      }
    } else {
      const span = Math.min(rows, Math.max(1, rowsOf(item)));
      if (column > 0) {
        column = 0;
        row++;
      }
      if (row + span > rows) newPage();
      page.push({ item, row, column: 0, rowSpan: span });
      row += span;
    }
  }
  newPage();
  return pages;
}
