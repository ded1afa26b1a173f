import { dataTable, h, setChildren, setHidden, setText } from '../../app/dom';
import { download } from '../../app/exportFigure';
import type { LessonApi } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import type { Point } from '../../math';
import { checkOutput, differenceRows } from './checkOutput';
import { type SplineKind, expectedOutput } from './splineRows';
import { DATASET_FILES, datasetText } from './datasetFile';
import { DATASETS, type BezierSplinesModel, type Dataset } from './model';
import type { BezierSplinesState } from './state';

type Api = LessonApi<BezierSplinesState, BezierSplinesModel>;
type Source = Dataset | 'points';

const SPLINES: { value: SplineKind; label: string }[] = [
  { value: 'C1', label: 'C¹ (computeSplineC1)' },
  { value: 'C2', label: 'C² (computeSplineC2)' },
];
const SOURCES: { value: Source; label: string }[] = [
  { value: 'infinity', label: 'infinity' },
  { value: 'spiral', label: 'spiral' },
  { value: 'semicircle', label: 'semi' },
  { value: 'points', label: 'the points in the figure' },
];

/** Radio buttons for a choice of this section only (not in the link): a fieldset with its legend. */
function choices<V extends string>(
  name: string,
  legend: string,
  options: { value: V; label: string }[],
  initial: V,
  changed: () => void,
) {
  const inputs = options.map(({ value }) =>
    h('input', {
      type: 'radio',
      name,
      value,
      id: `${name}-${value}`,
      checked: value === initial,
      onchange: changed,
    }),
  );
  return {
    element: h(
      'fieldset',
      {},
      h('legend', {}, legend),
      ...options.map(({ value, label }, i) =>
        h('label', { class: 'toggle', for: `${name}-${value}` }, inputs[i], label),
      ),
    ),
    value: () => (inputs.find((input) => input.checked)?.value ?? initial) as V,
  };
}

/** Buttons that save the lesson's three datasets as infinity.txt, spiral.txt, semi.txt (made on click, no network). */
export function datasetDownloads(api: Api): HTMLElement {
  return h(
    'div',
    {},
    h(
      'p',
      { class: 'note' },
      'The lesson’s own infinity, spiral and semi (the practical’s names; its data files are not in the notes), as the grid draws them: one point a line, x then y. If your program reads the number of points first, add that line.',
    ),
    h(
      'div',
      { class: 'button-row' },
      ...DATASETS.map((dataset) =>
        h(
          'button',
          {
            type: 'button',
            onclick: () =>
              download(
                new Blob([datasetText(api.get()[dataset])], { type: 'text/plain' }),
                DATASET_FILES[dataset],
              ),
          },
          `Download ${DATASET_FILES[dataset]}`,
        ),
      ),
    ),
  );
}

/** "Check your computeSplineC1 or computeSplineC2 output": paste, choose the spline and the points, read what differs and why. */
export function checkTools(api: Api) {
  const check = () => run(api.get());
  const spline = choices('bs-check-spline', 'Spline', SPLINES, 'C2', check);
  const source = choices('bs-check-points', 'Points', SOURCES, 'points', check);
  const pasted = h('textarea', {
    id: 'bs-check-output',
    rows: 8,
    spellcheck: 'false',
    autocomplete: 'off',
    oninput: check,
  });
  const expecting = h('p', { class: 'note' });
  const summary = h('p', { role: 'status', 'aria-live': 'polite', class: 'bs-check-summary' });
  const why = h('ul', { 'aria-label': 'Likely why' });
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  const table = dataTable(
    'Control points that differ',
    ['row', 'control point', 'expected', 'yours', 'by'],
    body,
  );
  const tableBox = h('div', { class: 'table-scroll' }, table);
  let points: readonly Point[] = [];

  const pointsOf = (s: BezierSplinesState): Point[] => {
    const chosen = source.value();
    return chosen === 'points' ? s.points : s[chosen];
  };

  function run(state: BezierSplinesState) {
    points = pointsOf(state);
    const kind = spline.value();
    const n = points.length - 1;
    const count = expectedOutput(points, kind).length;
    setText(
      expecting,
      `${points.length} points, n = ${n} pieces: ${kind === 'C1' ? 'computeSplineC1' : 'computeSplineC2'} returns ${kind === 'C1' ? '2n + 1' : '3n + 1'} = ${count} rows, x and y in each.`,
    );
    const text = pasted.value;
    const verdict = text.trim() === '' ? null : checkOutput(text, points, kind);
    // Every text from the paste is written as text (textContent), never as markup.
    setText(summary, verdict?.summary ?? '');
    summary.dataset.status = verdict?.status ?? '';
    setChildren(why, ...(verdict?.why ?? []).map((line) => h('li', {}, line)));
    setHidden(why, !verdict || verdict.why.length === 0);
    rows.set((verdict ? differenceRows(verdict) : []).map((cells) => ({ cells })));
    setHidden(tableBox, !verdict || verdict.differences.length === 0);
  }

  const element = h(
    'section',
    { 'aria-labelledby': 'bs-check-title' },
    h('h3', { id: 'bs-check-title' }, 'Check your computeSplineC1 or computeSplineC2 output'),
    h(
      'p',
      {},
      'Paste the control points your program printed, as plain numbers: x and y of each, in the order it returns them (spaces, commas, semicolons, brackets and new lines may separate them). C¹ uses b₀ the midpoint of p₀p₁, as the practical suggests; C² the natural ends.',
    ),
    spline.element,
    source.element,
    expecting,
    h('label', { for: 'bs-check-output' }, 'Control points your program printed (x y per point)'),
    pasted,
    h('div', { class: 'button-row' }, h('button', { type: 'button', onclick: check }, 'Check')),
    summary,
    why,
    tableBox,
    h('h3', {}, 'The datasets'),
    datasetDownloads(api),
  );
  return {
    element,
    update(m: BezierSplinesModel) {
      // The points in the figure (or a dataset) changed: check the same paste against them.
      if (pointsOf(m.state) !== points) run(m.state);
    },
  };
}
