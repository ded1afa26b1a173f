import { h } from '../../app/dom';
import { bernstein, bezierDeviation, bezierPoint, distance } from '../../math';
import { formula, texNumber } from '../../render/formula';
import { type Experiment, drawBezier, drawPolygon } from './experiment';
import type { PropertiesState } from './state';

/** The control points that differ between "before" (q) and now (p). */
const movedPoints = (state: PropertiesState) =>
  state.p.flatMap((point, i) => (distance(point, state.q[i]) > 0 ? [i] : []));

export const local: Experiment = {
  id: 'local',
  title: 'No local control',
  sentence:
    'Moving one control point moves the whole curve, but an inner point of a long polygon has a small weight everywhere, so the curve barely follows it.',
  draw(painter, state, info) {
    const theme = painter.theme;
    const before = state.q;
    drawPolygon(painter, before, { alpha: 0.45 });
    drawBezier(painter, before, {
      color: theme.curveFaint,
      width: theme.sizes.curve,
      dash: [8, 6],
    });
    drawPolygon(painter, state.p);
    drawBezier(painter, state.p, { color: theme.curve });
    const { at, distance: largest } = bezierDeviation(before, state.p);
    if (largest > 0) {
      const from = bezierPoint(before, at);
      const to = bezierPoint(state.p, at);
      painter.arrow(from, to, { color: theme.accent, width: theme.sizes.line * 1.3 });
      if (!info.thumbnail) {
        painter.label(`max ${largest.toFixed(3)}`, to, {
          dx: 8,
          dy: -theme.sizes.label * 0.8,
          color: theme.accent,
          halo: true,
          bold: true,
        });
      }
    }
    for (const i of movedPoints(state)) {
      painter.arrow(state.q[i], state.p[i], {
        color: theme.muted,
        width: theme.sizes.thin,
        dash: [4, 4],
      });
      painter.dot(state.q[i], theme.curveFaint, theme.sizes.point);
    }
  },
  explain(state) {
    const n = state.p.length - 1;
    const moved = movedPoints(state);
    const { at, distance: largest } = bezierDeviation(state.q, state.p);
    if (moved.length === 0) {
      return [
        h(
          'p',
          {},
          'The dashed "before" curve is the current one. Drag an inner control point (or Tab to it and use the arrow keys) and compare.',
        ),
      ];
    }
    const nodes: Node[] = [
      h(
        'p',
        {},
        `Largest displacement of the curve: ${largest.toFixed(4)}, at t = ${at.toFixed(3)} (dashed: before; the orange arrow shows it).`,
      ),
    ];
    if (moved.length === 1) {
      const i = moved[0];
      const shift = distance(state.p[i], state.q[i]);
      // Only Pi changed, so P_after(t) − P_before(t) = W(N, i, t)·Δ: largest where W(N, i, ·) peaks, at t = i/N.
      const peak = bernstein(n, i, i / n);
      nodes.push(
        formula(
          `\\begin{aligned}P_{\\text{after}}(t) - P_{\\text{before}}(t) &= W(${n},${i},t)\\,\\Delta P_{${i}}\\\\ \\max_t W(${n},${i},t) &= W\\bigl(${n},${i},\\tfrac{${i}}{${n}}\\bigr) = ${texNumber(peak, 4)}\\\\ \\max_t |P_{\\text{after}} - P_{\\text{before}}| &= ${texNumber(peak, 4)} \\times ${texNumber(shift, 3)} = ${texNumber(peak * shift, 4)}\\end{aligned}`,
          true,
        ),
        h(
          'p',
          { class: 'note' },
          `P${i} moved by ${shift.toFixed(3)}, the curve by at most ${((100 * largest) / shift).toFixed(1)}% of that. Every point of the curve moved (there is no local control), yet none by much: the weight of P${i} is never more than ${peak.toFixed(3)}.`,
        ),
      );
    } else {
      nodes.push(
        h('p', { class: 'note' }, `Points moved: ${moved.map((i) => `P${i}`).join(', ')}.`),
      );
    }
    return nodes;
  },
};
