import { dataTable, fmtPoint, h, setHidden, setText } from '../../app/dom';
import { LiveRows } from '../../app/liveTable';
import { continuityName } from '../../kit/format';
import type { HermiteModel } from './model';

const NONE = 'One patch, no joins yet: add a point to chain a second patch on.';

/** The panel's section on the joins: how smooth the curve is at each inner point. */
export function joinsSection() {
  const text = h('p', {});
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  // Points to 2 decimals, as everywhere in the app; a heading may take two
  // lines, Continuity broken where its soft hyphen is (at 3 decimals the
  // table ran 384 px in a phone's 336).
  const table = dataTable(
    'Joins',
    ['Join', 'P′ before', 'P′ after', 'Conti\u00ADnuity'],
    body,
    'names',
  );
  return {
    element: h('section', {}, h('h2', {}, 'Joins'), text, table),
    update({ joins, onlyC1 }: HermiteModel) {
      setHidden(table, joins.length === 0);
      setText(
        text,
        joins.length
          ? `Both patches at an inner point use its one gradient, so P′ is the same on both sides: every join is C¹, measured here on the patches. ${onlyC1 ? `The second derivatives differ at ${onlyC1} of ${joins.length}: C¹ but not C². A spline that is C² as well is the next step.` : ''}`
          : NONE,
      );
      rows.set(
        joins.map((join) => ({
          cells: [
            `P${join.k}`,
            fmtPoint(join.before),
            fmtPoint(join.after),
            continuityName(join.continuity),
          ],
        })),
      );
    },
  };
}
