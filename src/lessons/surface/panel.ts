import { fmt, h, setAttr, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { radioGroup } from '../../app/panelControls';
import { rangeField } from '../../app/rangeControls';
import { LiveFormula, SLOT, formula, slotPoint } from '../../render/formula';
import type { SurfaceModel } from './model';
import { netTable } from './netTable';
import { notesSymbols, rowsSlip } from './notes';
import type { Coordinate, SurfaceLook, SurfaceState } from './state';
import { continuityName, joinVerdict } from './notation';
import './surface.css';
import { gestures } from '../../kit/gestures';
import { trimmed } from '../../kit/format';

/** Digits of the check table: enough to see that three ways agree to the last digit shown. */
/** Digits of the point three ways: the rows agree to all of them; the exact value is on the row. */
const DIGITS = 6;
const vector = (p: readonly number[]) => p.map((value) => fmt(value, 4));
const slots = (count: number) => Array.from({ length: count }, () => SLOT);
const row = (count: number) => `\\begin{bmatrix}${slots(count).join(' & ')}\\end{bmatrix}`;
const column = (count: number) => `\\begin{bmatrix}${slots(count).join('\\\\')}\\end{bmatrix}`;
const square = `\\begin{bmatrix}${[0, 1, 2, 3].map(() => slots(4).join(' & ')).join('\\\\')}\\end{bmatrix}`;

export function surfacePanel(
  api: LessonApi<SurfaceState, SurfaceModel>,
): LessonPanel<SurfaceState, SurfaceModel> {
  const v = rangeField(api, {
    label: 'v',
    name: 'v',
    min: 0,
    max: 1,
    step: 0.01,
    get: (s) => s.v,
    set: (s, value) => ({ ...s, v: value }),
    coalesce: 'surface-v',
    numberField: true,
  });

  const look = radioGroup<SurfaceState, SurfaceLook>(api, {
    name: 'surface-look',
    choices: [
      { value: 'shaded', label: 'Shaded, lit from a fixed light' },
      { value: 'lines', label: 'Iso-parameter lines in u and v' },
    ],
    get: (s) => s.look,
    set: (s, value) => ({ ...s, look: value }),
  });
  const coordinate = radioGroup<SurfaceState, Coordinate>(api, {
    name: 'surface-coordinate',
    choices: (['x', 'y', 'z'] as const).map((value) => ({ value, label: `${value} coordinate` })),
    get: (s) => s.coordinate,
    set: (s, value) => ({ ...s, coordinate: value }),
  });

  const pointBody = h('tbody', {});
  const pointRows = new LiveRows(pointBody);
  const derivatives = new LiveFormula(true);
  const matrixFactors = new LiveFormula(true);
  const matrixProduct = new LiveFormula(true);
  const weightBody = h('tbody', {});
  const weightRows = new LiveRows(weightBody);
  const weightSum = h('output', { 'aria-label': 'Sum of the 16 weights' });
  const joinText = h('p', {});
  // The slides' “for 0 ≤ v ≤ 1” of the curve in u: beside the scene that builds it.
  const slip = rowsSlip();
  const firstNet = netTable(api, 'net');
  const secondNet = netTable(api, 'secondNet');
  const joinSection = h(
    'section',
    {},
    h('h2', {}, 'Two patches joined'),
    h(
      'p',
      {},
      'The second net Q continues the first, P, across the edge x = 3: its row Q₀,ₙ should be the first net’s row P₃,ₙ (C⁰), and each leg Q₀,ₙ → Q₁,ₙ should continue P₂,ₙ → P₃,ₙ in a straight line with the same length (C¹).',
    ),
    joinText,
    secondNet.element,
  );

  const element = h(
    'div',
    { class: 'lesson-text surface-text' },
    h(
      'p',
      {},
      'A bicubic Bézier patch is a surface in space made from 16 control points Pₘ,ₙ (m, n = 0 … 3). Each row and each column of the control net is the control polygon of a cubic; the surface is the tensor product of two families of cubics:',
    ),
    formula(
      '\\mathbf{P}(u,v)=\\sum_{m=0}^{3}\\sum_{n=0}^{3} f_m(u)\\,f_n(v)\\,\\mathbf{P}_{m,n},\\qquad 0\\le u,v\\le 1',
      true,
    ),
    slip,
    notesSymbols(),
    h(
      'p',
      { class: 'note' },
      `u is the lesson’s parameter (the slider with Play above); v is the slider below. To turn the patch, ${gestures().orbit}; to zoom, ${gestures().zoom}. A control point moves in the plane facing you: ${gestures().move}${gestures().move.includes('Tab') ? ' (Shift: along one axis; Ctrl+↑/↓: along z)' : ''}.`,
    ),
    v.element,
    h('div', { class: 'lesson-tools' }, ...look.labels),
    h('h2', {}, 'The point P(u, v), three ways'),
    h('p', {}, 'By the double sum, and by de Casteljau in u then v and in v then u:'),
    h(
      'table',
      { class: 'data-table names', 'aria-label': 'The point P(u, v) three ways' },
      h(
        'thead',
        {},
        h('tr', {}, ...['By', 'x', 'y', 'z'].map((c) => h('th', { scope: 'col' }, c))),
      ),
      pointBody,
    ),
    h('h2', {}, 'Tangents and normal at P(u, v)'),
    derivatives.element,
    h('h2', {}, 'Matrix form, one coordinate'),
    h('div', { class: 'lesson-tools' }, ...coordinate.labels),
    formula(
      'M=\\begin{bmatrix}1&0&0&0\\\\-3&3&0&0\\\\3&-6&3&0\\\\-1&3&-3&1\\end{bmatrix},\\quad U=\\begin{bmatrix}1&u&u^2&u^3\\end{bmatrix},\\quad V=\\begin{bmatrix}1&v&v^2&v^3\\end{bmatrix}',
      true,
    ),
    matrixFactors.element,
    matrixProduct.element,
    h('h2', {}, 'The 16 weights fₘ(u)·fₙ(v)'),
    h(
      'table',
      { class: 'data-table', 'aria-label': 'The 16 weights' },
      h(
        'thead',
        {},
        h(
          'tr',
          {},
          h('th', { scope: 'col' }, h('span', { class: 'visually-hidden' }, 'Row')),
          ...[0, 1, 2, 3].map((n) => h('th', { scope: 'col' }, `n = ${n}`)),
        ),
      ),
      weightBody,
    ),
    h(
      'p',
      {},
      'Their sum: ',
      weightSum,
      ' (never negative, always 1: the patch lies in the convex hull of its net).',
    ),
    joinSection,
    h('h2', {}, 'The control net P'),
    firstNet.element,
  );

  return {
    element,
    update(m, state) {
      setHidden(slip, state.mode !== 'rows');
      look.update(state);
      coordinate.update(state);
      v.update(state);
      const three = (name: string, p: readonly number[]) => ({
        cells: [name, ...p.map((value) => fmt(value, DIGITS))],
        data: { exact: p.map(String).join(',') },
      });
      pointRows.set([
        three('Σ fₘ fₙ Pₘ,ₙ', m.point),
        three('u, then v', m.uThenV.point),
        three('v, then u', m.vThenU.point),
      ]);
      derivatives.set(
        `\\begin{aligned}\\partial\\mathbf{P}/\\partial u &= ${slotPoint(3)}\\\\ \\partial\\mathbf{P}/\\partial v &= ${slotPoint(3)}\\\\ \\partial\\mathbf{P}/\\partial u\\times\\partial\\mathbf{P}/\\partial v &= ${slotPoint(3)}\\\\ \\mathbf{n} &= ${m.normal ? slotPoint(3) : '\\text{undefined (the tangents are parallel)}'}\\end{aligned}`,
        [
          ...vector(m.du),
          ...vector(m.dv),
          ...vector(m.crossProduct),
          ...(m.normal ? vector(m.normal) : []),
        ],
      );
      const f = m.matrix;
      const c = state.coordinate;
      matrixFactors.set(
        `\\begin{aligned}U M &= ${row(4)}\\\\ M^{\\mathsf T} V^{\\mathsf T} &= ${row(4)}^{\\mathsf T}\\end{aligned}`,
        [...f.UM, ...f.VM].map((value) => fmt(value, 4)),
      );
      matrixProduct.set(
        `${c}(u,v) = U M\\,${square}\\,M^{\\mathsf T} V^{\\mathsf T} = ${row(4)}\\,${column(4)} = ${SLOT}`,
        [
          ...f.B.flat().map((value) => fmt(value, 2)),
          ...f.UMB.map((value) => fmt(value, 4)),
          ...f.VM.map((value) => fmt(value, 4)),
          fmt(f.value, 6),
        ],
      );
      weightRows.set(
        m.weights.map((weights, i) => ({
          heading: true,
          cells: [`m = ${i}`, ...weights.map((w) => fmt(w, 4))],
        })),
      );
      // 1, not 0.99999999999999978: the sum is 1, and the last bits are
      // rounding (the exact value stays on the element for scripts).
      setText(weightSum, trimmed(m.weightSum, 12));
      setAttr(weightSum, 'data-exact', String(m.weightSum));
      setHidden(joinSection, !m.join);
      if (m.join) {
        setText(
          joinText,
          `Across the edge: ${joinVerdict(m.join)}. Column by column: ${m.join.columns.map((value, n) => `n = ${n}: ${continuityName(value)}`).join(', ')}.`,
        );
        secondNet.update(state);
      }
      firstNet.update(state);
    },
  };
}
