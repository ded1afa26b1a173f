import { fmt, fmtPoint, h, setChildren } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { type Point, quadraticSplineC1, snapJoint } from '../../math';
import { verdict } from './drawInspector';
import { asCubic, type BezierSplinesModel } from './model';
import { inspector } from './script';
import { type BezierSplinesState, c2ControlPoints, midpoint } from './state';

const joints = (q: readonly Point[]) => q.filter((_, j) => j % 3 === 0);

/** An edit of the chain shows at least the verdicts, so its effect is read at once. */
const withVerdicts = (s: BezierSplinesState) => Math.max(s.step, inspector.stepOf(s, 'verdicts'));

/** The inspector's panel: every joint's numbers, "Make G¹ / C¹" at each joint, and chains to start from. */
export function inspectorTools(api: LessonApi<BezierSplinesState, BezierSplinesModel>) {
  // One column a joint and one row a quantity: two joints' ten numbers fit a
  // 336 px phone panel, where a row a joint ran 783 px wide.
  const header = h('tr', {});
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  const table = h(
    'table',
    { class: 'data-table', 'aria-label': 'Continuity at each joint' },
    h('thead', {}, header),
    body,
  );
  let jointHeads: HTMLTableCellElement[] = [];
  const snaps = h('div', { class: 'button-row' });
  let jointCount = -1;
  const snap = (k: number, mode: 'G1' | 'C1') => () => {
    const s = api.get();
    const q = s.handBuilt;
    const j = 3 * k;
    const after = snapJoint(q[j - 1], q[j], q[j + 1], mode);
    api.set({
      ...s,
      handBuilt: q.map((c, i) => (i === j + 1 ? after : c)),
      step: withVerdicts(s),
    });
  };
  const preset = (label: string, make: (q: Point[]) => Point[]) =>
    h(
      'button',
      {
        type: 'button',
        onclick: () => {
          const s = api.get();
          api.set({ ...s, handBuilt: make(s.handBuilt), step: withVerdicts(s) });
        },
      },
      label,
    );
  const presets = h(
    'div',
    { class: 'button-row' },
    preset('C² spline through the joints', (q) => c2ControlPoints(joints(q))),
    preset('C¹ quadratic spline through the joints', (q) => {
      const p = joints(q);
      const pieces = quadraticSplineC1(p, midpoint(p[0], p[1])).map(asCubic);
      return [p[0], ...pieces.flatMap((piece) => piece.slice(1))];
    }),
    preset('Sharp corner at joint 1', (q) =>
      q.map((c, i) => (i === 2 || i === 4 ? q[3].slice() : c)),
    ),
  );
  return {
    element: h(
      'div',
      {},
      h('h3', {}, 'Every joint'),
      h('div', { class: 'table-scroll' }, table),
      snaps,
      h('h3', {}, 'Start from'),
      presets,
    ),
    update(m: BezierSplinesModel) {
      if (m.joints.length !== jointCount) {
        jointCount = m.joints.length;
        jointHeads = m.joints.map((_, i) =>
          h('th', { scope: 'col', 'data-joint': String(i + 1) }, `joint ${i + 1}`),
        );
        setChildren(header, h('th', { scope: 'col' }, 'at the joint'), jointHeads);
        setChildren(
          snaps,
          m.joints.flatMap((_, i) => [
            h(
              'button',
              { type: 'button', onclick: snap(i + 1, 'G1') },
              `Make G¹ at joint ${i + 1}`,
            ),
            h(
              'button',
              { type: 'button', onclick: snap(i + 1, 'C1') },
              `Make C¹ at joint ${i + 1}`,
            ),
          ]),
        );
      }
      m.joints.forEach((r, i) => {
        if (jointHeads[i].dataset.continuity !== r.continuity)
          jointHeads[i].dataset.continuity = r.continuity;
      });
      const row = (name: string, cell: (r: (typeof m.joints)[number]) => string) => ({
        heading: true,
        data: { quantity: name },
        cells: [name, ...m.joints.map(cell)],
      });
      const maybe = (x: number, text: (x: number) => string) =>
        Number.isFinite(x) ? text(x) : '—';
      rows.set([
        row('verdict', (r) => verdict(r.continuity)),
        row('P′ left', (r) => fmtPoint(r.leftVelocity)),
        row('P′ right', (r) => fmtPoint(r.rightVelocity)),
        row('angle', (r) => maybe(r.angle, (a) => `${fmt(a, 1)}°`)),
        row('ratio', (r) => maybe(r.lengthRatio, (x) => fmt(x, 3))),
        row('P″ left', (r) => fmtPoint(r.leftSecond)),
        row('P″ right', (r) => fmtPoint(r.rightSecond)),
        row('κ left', (r) => maybe(r.leftCurvature, (x) => fmt(x, 3))),
        row('κ right', (r) => maybe(r.rightCurvature, (x) => fmt(x, 3))),
      ]);
    },
  };
}
