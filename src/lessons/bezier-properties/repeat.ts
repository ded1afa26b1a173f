import { h } from '../../app/dom';
import { bernsteinBasis, bezierDerivative, bezierPoint, norm } from '../../math';
import { formula, texNumber } from '../../render/formula';
import { type Experiment, drawBezier, drawMarked, drawPolygon, texT } from './experiment';
import { controlPoints } from './state';

export const repeat: Experiment = {
  id: 'repeat',
  title: 'Repeated control points',
  sentence:
    'A control point listed several times gets the sum of their weights, so the curve is pulled toward it; press "Add a copy" (or step forward) and watch.',
  draw(painter, state, info) {
    const theme = painter.theme;
    const p = controlPoints(state);
    drawBezier(painter, state.p, {
      color: theme.curveFaint,
      width: theme.sizes.curve,
      dash: [8, 6],
    });
    drawPolygon(painter, state.p);
    drawBezier(painter, p, { color: theme.curve });
    const pulled = state.p[state.r];
    painter.ring(pulled, theme.sizes.handle * (1.6 + 0.5 * state.k), {
      color: theme.accent,
      width: theme.sizes.line,
    });
    if (!info.thumbnail && state.k > 0) {
      painter.label(`×${state.k + 1}`, pulled, {
        dx: -theme.sizes.handle * 2,
        dy: theme.sizes.label,
        align: 'right',
        color: theme.accent,
        halo: true,
        bold: true,
      });
    }
    drawMarked(painter, bezierPoint(p, state.t), 'P(t)', info);
  },
  explain(state) {
    const p = controlPoints(state);
    const n = p.length - 1;
    const copies = state.k + 1;
    const weights = bernsteinBasis(n, state.t);
    // The copies of P_r sit at indices r … r + k of the repeated list.
    const total = weights.slice(state.r, state.r + copies).reduce((a, b) => a + b, 0);
    const once = bernsteinBasis(state.p.length - 1, state.t)[state.r];
    return [
      h(
        'p',
        {},
        `P${state.r} appears ${copies} time${copies === 1 ? '' : 's'}: the curve has ${n + 1} control points, degree ${n}. Dashed: the curve with P${state.r} once.`,
      ),
      formula(
        `\\begin{aligned}&\\text{weight of } P_{${state.r}} \\text{ at } t = ${texT(state.t)}:\\\\ &\\sum_{j=${state.r}}^{${state.r + copies - 1}} W(${n},j,t) = ${texNumber(total, 4)}\\quad(\\text{once: } ${texNumber(once, 4)})\\end{aligned}`,
        true,
      ),
    ];
  },
};

export const closed: Experiment = {
  id: 'closed',
  title: 'A closed curve',
  sentence:
    'Repeat the first point at the end, P0 = PN, and the curve closes; it is smooth there only if PN−1, P0 and P1 lie on one line.',
  draw(painter, state, info) {
    const theme = painter.theme;
    const p = controlPoints(state);
    drawPolygon(painter, p);
    drawBezier(painter, p, { color: theme.curve });
    const hodograph = bezierDerivative(p);
    const start = hodograph[0];
    const end = hodograph[hodograph.length - 1];
    const scale = 0.35;
    const p0 = p[0];
    painter.arrow(p0, [p0[0] + scale * start[0], p0[1] + scale * start[1]], {
      color: painter.color(0),
      width: theme.sizes.line * 1.3,
    });
    painter.arrow([p0[0] - scale * end[0], p0[1] - scale * end[1]], p0, {
      color: painter.color(1),
      width: theme.sizes.line * 1.3,
    });
    drawMarked(painter, p0, `P_0 = P_{${p.length - 1}}`, info, theme.accent);
    drawMarked(painter, bezierPoint(p, state.t), 'P(t)', info, painter.color(2));
  },
  explain(state) {
    const p = controlPoints(state);
    const n = p.length - 1;
    const hodograph = bezierDerivative(p);
    const start = hodograph[0];
    const end = hodograph[hodograph.length - 1];
    if (norm(start) === 0 || norm(end) === 0) {
      return [
        h(
          'p',
          {},
          'A neighbour of P0 sits on it, so one end tangent is zero and the corner cannot be measured: move P1 or the last point away from P0.',
        ),
      ];
    }
    const angle =
      (Math.atan2(start[0] * end[1] - start[1] * end[0], start[0] * end[0] + start[1] * end[1]) *
        180) /
      Math.PI;
    const smooth = Math.abs(angle) < 0.5;
    return [
      formula(`P'(0) = ${n}(P_1 - P_0),\\qquad P'(1) = ${n}(P_0 - P_{${n - 1}})`, true),
      h(
        'p',
        {},
        smooth
          ? `The end tangents agree in direction (within ${Math.abs(angle).toFixed(2)}°): the closed curve is smooth at P0.`
          : `The arriving and the leaving tangent (arrows, 0.35 × true length) meet at ${Math.abs(angle).toFixed(1)}°: the curve closes with a corner at P0. Drag P1 or P${n - 1} in line with P0 to smooth it.`,
      ),
    ];
  },
};
