import type { KitFigure } from '../../kit/lesson';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import { drawParts } from './drawParts';
import type { BezierSplinesModel } from './model';
import { firstControl, givenPoints, handBuilt, tangentTips } from './points';
import type { BezierSplinesState } from './state';

/** Everything the current part draws, so "fit" shows all of it. */
function shownPoints(m: BezierSplinesModel): Point[] {
  const { part, points: p, firstControl: b } = m.state;
  switch (part) {
    case 'inspector':
      // With the comb's tips, drawn at the scene's last step: the view is
      // fitted once a scene, so its first step leaves room for them too.
      return [...m.state.handBuilt, ...m.comb.map(([, tip]) => tip)];
    case 'quadratic':
      return [...p, ...b, ...m.quadraticControls];
    case 'system':
      return [...p, ...m.system.controls];
    case 'worked':
      return [...p, ...m.worked.c1.output, ...m.worked.c2.controls];
    case 'degree':
      return [...p, ...m.degree.row.c1.flat(), ...m.degree.continued];
    case 'catmull':
      return [...p, ...m.hermite.flat(), ...m.alphas.flatMap((a) => a.segments.flat())];
    default:
      return [...p, ...m.movedPoints];
  }
}

export const mainFigure: KitFigure<BezierSplinesState, BezierSplinesModel> = {
  id: 'main',
  title: 'Bézier splines: the points, the pieces and how they join',
  kind: 'geometry',
  bounds: (m) => boundsOf(shownPoints(m)),
  draw(painter, m, info) {
    drawParts[m.state.part](painter, m, info);
    // The given points (under their handles): what every step starts from.
    const given =
      m.state.part === 'inspector'
        ? m.state.handBuilt.filter((_, j) => j % 3 === 0)
        : m.state.points;
    for (const q of given) painter.dot(q, painter.theme.ink);
    if (m.oneSpot)
      painter.note(
        'All the points are on one spot: every piece shrinks to that point, so the spline is a single point with no direction, and its joins have nothing to match.',
      );
  },
  // Each list shows its handles in the parts and steps that have them.
  points: [givenPoints, firstControl, tangentTips, handBuilt],
  addTo: givenPoints,
};
