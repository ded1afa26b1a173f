import { h } from '../../app/dom';
import { add, bezierDerivative, bezierPoint, norm, scale, subtract } from '../../math';
import { formula, texPoint } from '../../render/formula';
import { type Experiment, drawBezier, drawMarked, drawPolygon, texT } from './experiment';
import { controlPoints } from './state';

/** The end tangents P′(0), P′(1) and P′(t): the hodograph's control points and value. */
function tangents(points: readonly (readonly number[])[], t: number) {
  const hodograph = bezierDerivative(points);
  return {
    start: hodograph[0],
    end: hodograph[hodograph.length - 1],
    at: points.length > 1 ? bezierPoint(hodograph, t) : hodograph[0],
  };
}

/**
 * Tangent arrows are drawn at half their true length: at full length (three
 * legs of a cubic's polygon) they shrink the curve to a corner of the figure,
 * while half still reaches past P1, showing the speed is N times the leg.
 */
const ARROW_SCALE = 0.5;

export const ends: Experiment = {
  id: 'ends',
  title: 'End points and end tangents',
  sentence:
    'The curve starts at P0 and ends at PN, leaving along the first leg of the polygon and arriving along the last, with speed N times the leg: P′(0) = N(P1 − P0), P′(1) = N(PN − PN−1).',
  extent(state) {
    const p = controlPoints(state);
    const d = tangents(p, state.t);
    return [
      add(p[0], scale(d.start, ARROW_SCALE)),
      add(p[p.length - 1], scale(d.end, ARROW_SCALE)),
      add(bezierPoint(p, state.t), scale(d.at, ARROW_SCALE)),
    ];
  },
  draw(painter, state, info) {
    const theme = painter.theme;
    const p = controlPoints(state);
    const n = p.length - 1;
    const d = tangents(p, state.t);
    drawPolygon(painter, p);
    drawBezier(painter, p, { color: theme.curve });
    const first = p[0];
    const last = p[n];
    const here = bezierPoint(p, state.t);
    const arrows: [readonly number[], readonly number[], string, string][] = [
      [first, d.start, painter.color(0), "½P'(0)"],
      [last, d.end, painter.color(1), "½P'(1)"],
      [here, d.at, painter.color(2), "½P'(t)"],
    ];
    for (const [from, vector, color, name] of arrows) {
      const tip = add(from, scale(vector, ARROW_SCALE));
      painter.arrow(from, tip, { color, width: theme.sizes.line * 1.4 });
      if (!info.thumbnail && norm(vector) > 0) {
        painter.label(name, tip, {
          dx: 6,
          dy: -theme.sizes.label * 0.6,
          color,
          halo: true,
          bold: true,
        });
      }
    }
    drawMarked(painter, first, 'P(0) = P_0', info, painter.color(0));
    drawMarked(painter, last, `P(1) = P_{${n}}`, info, painter.color(1));
    drawMarked(painter, here, 'P(t)', info, painter.color(2));
  },
  explain(state) {
    const p = controlPoints(state);
    const n = p.length - 1;
    const d = tangents(p, state.t);
    const nodes: Node[] = [
      formula(
        `\\begin{aligned}P(0) &= P_0 = ${texPoint(p[0])}\\\\ P(1) &= P_{${n}} = ${texPoint(p[n])}\\\\ P'(0) &= ${n}(P_1 - P_0) = ${texPoint(d.start)}\\\\ P'(1) &= ${n}(P_{${n}} - P_{${n - 1}}) = ${texPoint(d.end)}\\\\ P'(${texT(state.t)}) &= ${texPoint(d.at)}\\end{aligned}`,
        true,
      ),
      h(
        'p',
        {},
        `Speeds: |P′(0)| = ${norm(d.start).toFixed(3)}, |P′(1)| = ${norm(d.end).toFixed(3)}, |P′(t)| = ${norm(d.at).toFixed(3)}.`,
      ),
      h(
        'p',
        { class: 'note' },
        'The arrows are drawn at half their true length, in the units of the grid: a speed, not just a direction. For a cubic, half of 3(P1 − P0) still reaches past P1. Drag P1 along the first leg: the start tangent keeps its direction and changes its length.',
      ),
    ];
    if (norm(subtract(p[1], p[0])) === 0) {
      nodes.push(
        h(
          'p',
          {},
          'P1 sits on P0, so P′(0) = 0: the curve starts with zero speed, and leaves toward the next distinct control point instead (its direction comes from a higher derivative).',
        ),
      );
    }
    if (norm(subtract(p[n], p[n - 1])) === 0) {
      nodes.push(
        h('p', {}, `P${n - 1} sits on P${n}, so P′(1) = 0: the curve arrives with zero speed.`),
      );
    }
    return nodes;
  },
};
