import { h, dataTable } from '../../app/dom';
import { bezierPoint, controlPolygonGap, splitBezier } from '../../math';
import { formula, texPoint } from '../../render/formula';
import { type Experiment, drawBezier, drawMarked, texT } from './experiment';
import { controlPoints } from './state';

/** The pieces after splitting every piece at t, `levels` times. */
export function splitPieces(
  p: readonly (readonly number[])[],
  t: number,
  levels: number,
): (readonly (readonly number[])[])[] {
  let pieces = [p];
  for (let j = 0; j < levels; j++) pieces = pieces.flatMap((piece) => splitBezier(piece, t));
  return pieces;
}

export const split: Experiment = {
  id: 'split',
  title: 'Subdivision',
  sentence:
    'De Casteljau at t splits the curve into two Bézier curves with their own control polygons; split the pieces again and again and the polygons converge to the curve, fast.',
  draw(painter, state, info) {
    const theme = painter.theme;
    const p = controlPoints(state);
    const pieces = splitPieces(p, state.t, state.k);
    painter.polyline(p, {
      color: theme.polygon,
      width: theme.sizes.thin,
      dash: [6, 5],
      alpha: 0.6,
    });
    drawBezier(painter, p, { color: theme.curve, width: theme.sizes.curve });
    pieces.forEach((piece, j) => {
      const color = painter.color(j % 2);
      painter.polyline(piece, { color, width: theme.sizes.line * 1.2, alpha: 0.9 });
      for (const point of piece)
        painter.dot(point, color, theme.sizes.point * (state.k > 2 ? 0.6 : 0.9));
    });
    if (state.k >= 1) drawMarked(painter, bezierPoint(p, state.t), 'P(t)', info);
  },
  explain(state) {
    const p = controlPoints(state);
    const nodes: Node[] = [];
    if (state.k > 0 && (state.t === 0 || state.t === 1)) {
      nodes.push(
        h(
          'p',
          {},
          `At t = ${state.t} one of the two pieces is the single point P${state.t === 0 ? '0' : `${p.length - 1}`} and the other is the whole curve again: nothing is gained. Choose t inside (0, 1).`,
        ),
      );
    }
    if (state.k === 0) {
      nodes.push(
        h('p', {}, 'Not split yet. Press "Split every piece" (or step forward); t sets where.'),
      );
    } else {
      const [left, right] = splitBezier(p, state.t);
      nodes.push(
        h(
          'p',
          {},
          `First split at t = ${texT(state.t)}: the left polygon is P0,0 … P${p.length - 1},0 of de Casteljau, the right one P${p.length - 1},0 … P0,${p.length - 1}.`,
        ),
        formula(`\\text{left: } ${left.map((q) => texPoint(q)).join(',\\ ')}`, true),
        formula(`\\text{right: } ${right.map((q) => texPoint(q)).join(',\\ ')}`, true),
      );
    }
    const rows = Array.from({ length: state.k + 1 }, (_, j) => {
      const pieces = splitPieces(p, state.t, j);
      const gap = Math.max(...pieces.map((piece) => controlPolygonGap(piece)));
      return h(
        'tr',
        { class: j === state.k ? 'current' : '' },
        h('td', {}, String(j)),
        h('td', {}, String(pieces.length)),
        h('td', {}, gap.toFixed(5)),
      );
    });
    nodes.push(
      dataTable(
        'Subdivision levels',
        ['Splits', 'Pieces', 'Largest polygon gap'],
        h('tbody', {}, rows),
      ),
      h(
        'p',
        { class: 'note' },
        'At t = 0.5 each split divides the gap between polygon and curve by about 4: far faster than raising the degree. This is how curves are drawn and intersected in practice.',
      ),
    );
    return nodes;
  },
};
