import { dataTable, fmt, fmtPoint, h, setChildren } from '../../app/dom';
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
  const body = h('tbody', {});
  const rows = new LiveRows(body);
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
      h(
        'div',
        { class: 'table-scroll' },
        dataTable(
          'Continuity at each joint',
          [
            'joint',
            'verdict',
            'P′ left',
            'P′ right',
            'angle',
            'ratio',
            'P″ left',
            'P″ right',
            'κ left',
            'κ right',
          ],
          body,
        ),
      ),
      snaps,
      h('h3', {}, 'Start from'),
      presets,
    ),
    update(m: BezierSplinesModel) {
      if (m.joints.length !== jointCount) {
        jointCount = m.joints.length;
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
      rows.set(
        m.joints.map((r, i) => ({
          heading: true,
          data: { joint: String(i + 1), continuity: r.continuity },
          cells: [
            String(i + 1),
            verdict(r.continuity),
            fmtPoint(r.leftVelocity),
            fmtPoint(r.rightVelocity),
            Number.isNaN(r.angle) ? '—' : `${fmt(r.angle, 1)}°`,
            Number.isFinite(r.lengthRatio) ? fmt(r.lengthRatio, 3) : '—',
            fmtPoint(r.leftSecond),
            fmtPoint(r.rightSecond),
            Number.isNaN(r.leftCurvature) ? '—' : fmt(r.leftCurvature, 3),
            Number.isNaN(r.rightCurvature) ? '—' : fmt(r.rightCurvature, 3),
          ],
        })),
      );
    },
  };
}
