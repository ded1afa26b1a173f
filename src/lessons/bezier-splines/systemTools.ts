import { continuityName, smallNumber, sub, words } from '../../kit/format';
import { dataTable, fmt, h, setAttr, setChildren, setHidden, setText } from '../../app/dom';
import { LiveRows } from '../../app/liveTable';
import type { BezierSplinesModel } from './model';

const full = (v: number) => String(v);

/** The C² system's panel: the matrix once the step shows it, then the solution beside the natural spline. */
export function systemTools() {
  const matrixHead = h('thead', {});
  const matrixBody = h('tbody', {});
  const matrix = new LiveRows(matrixBody);
  const matrixTable = h(
    'table',
    { class: 'data-table matrix', 'aria-label': 'The linear system' },
    matrixHead,
    matrixBody,
  );
  const solutionBody = h('tbody', {});
  const solution = new LiveRows(solutionBody);
  const residual = h('output', { 'aria-label': 'Residual' });
  const difference = h('output', { 'aria-label': 'Difference from the natural cubic spline' });
  const matrixPart = h(
    'div',
    {},
    h('h3', {}, 'The system A c = r'),
    h('div', { class: 'table-scroll' }, matrixTable),
  );
  const solutionPart = h(
    'div',
    {},
    h('h3', {}, 'Solved'),
    h('p', {}, 'Largest residual |A c − r| of any equation: ', residual),
    h(
      'p',
      {},
      'Largest difference from the natural cubic spline (cubicSplineC2, from naturalCubicDerivatives): ',
      difference,
    ),
    dataTable('Solved control points', ['', 'x', 'y', 'natural x', 'natural y'], solutionBody),
  );
  let size = 0;
  return {
    element: h('div', {}, matrixPart, solutionPart),
    update(m: BezierSplinesModel) {
      setHidden(matrixPart, !m.shown.has('matrix'));
      setHidden(solutionPart, !m.shown.has('solution'));
      const { equations, controls } = m.system;
      if (equations.length !== size) {
        size = equations.length;
        setChildren(
          matrixHead,
          h(
            'tr',
            {},
            h('th', {}, 'row'),
            ...m.names.map((n) => h('th', { scope: 'col' }, n)),
            h('th', {}, 'r x'),
            h('th', {}, 'r y'),
          ),
        );
      }
      matrix.set(
        equations.map((e) => ({
          heading: true,
          cells: [
            e.kind === 'point'
              ? `p${sub(e.at)}`
              : `${e.kind === 'natural' ? 'natural' : continuityName(e.kind)} at p${sub(e.at)}`,
            ...e.coefficients.map((v) => (v === 0 ? '·' : words(v))),
            fmt(e.right[0]),
            fmt(e.right[1]),
          ],
        })),
      );
      // Written as a lecturer writes it; the exact value stays on the element for scripts.
      setText(residual, smallNumber(m.system.residual));
      setAttr(residual, 'data-exact', String(m.system.residual));
      setText(difference, smallNumber(m.difference));
      setAttr(difference, 'data-exact', String(m.difference));
      const natural = [m.natural[0][0], ...m.natural.flatMap((seg) => seg.slice(1))];
      solution.set(
        controls.map((c, j) => ({
          heading: true,
          data: {
            exact: `${full(c[0])},${full(c[1])};${full(natural[j][0])},${full(natural[j][1])}`,
          },
          cells: [
            m.names[j],
            fmt(c[0], 4),
            fmt(c[1], 4),
            fmt(natural[j][0], 4),
            fmt(natural[j][1], 4),
          ],
        })),
      );
    },
  };
}
