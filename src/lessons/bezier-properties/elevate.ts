import { h, dataTable } from '../../app/dom';
import { bezierDeviation, controlPolygonGap, elevateDegree } from '../../math';
import { formula, texPoint } from '../../render/formula';
import { type Experiment, drawBezier, drawPolygon } from './experiment';
import { controlPoints } from './state';

/** The polygons after 0, 1, …, k elevations. */
function chain(p: readonly (readonly number[])[], k: number): (readonly (readonly number[])[])[] {
  const polygons = [p];
  for (let j = 0; j < k; j++) polygons.push(elevateDegree(polygons[j]));
  return polygons;
}

/** Largest distance between the original curve and the elevated one, over 1000 samples. */
export const elevationDeviation = (
  original: readonly (readonly number[])[],
  elevated: readonly (readonly number[])[],
) => bezierDeviation(original, elevated, 1000).distance;

export const elevate: Experiment = {
  id: 'elevate',
  title: 'Degree elevation',
  sentence:
    'Raising the degree replaces N + 1 control points by N + 2 on the same curve; repeat it and the control polygon closes in on the curve.',
  draw(painter, state, info) {
    const theme = painter.theme;
    const q = controlPoints(state);
    if (state.k > 0) drawPolygon(painter, state.p, { alpha: 0.5 });
    drawBezier(painter, q, { color: theme.curve });
    painter.polyline(q, { color: painter.color(0), width: theme.sizes.line });
    const small = q.length > 10;
    q.forEach((point, i) => {
      painter.dot(point, painter.color(0), theme.sizes.point * (small ? 0.7 : 1));
      if (!info.thumbnail && state.k > 0 && !small) {
        painter.label(`Q_{${i}}`, point, {
          dx: -4,
          dy: theme.sizes.label * 0.9,
          align: 'right',
          color: painter.color(0),
          halo: true,
          size: theme.sizes.small,
        });
      }
    });
  },
  explain(state) {
    const polygons = chain(state.p, state.k);
    const q = polygons[polygons.length - 1];
    const n0 = state.p.length - 1;
    const n = q.length - 1;
    const deviation = elevationDeviation(state.p, q);
    const nodes: Node[] = [
      formula(
        '\\begin{aligned}Q_0 &= P_0,\\qquad Q_{N+1} = P_N\\\\ Q_i &= \\tfrac{i}{N+1}P_{i-1} + \\bigl(1 - \\tfrac{i}{N+1}\\bigr)P_i\\end{aligned}',
        true,
      ),
      h(
        'p',
        {},
        state.k === 0
          ? `Degree ${n0}, not raised yet. Press "Raise the degree" (or step forward).`
          : `Degree ${n0} raised ${state.k} time${state.k === 1 ? '' : 's'}: degree ${n}, ${n + 1} control points (solid), the original polygon dashed.`,
      ),
      h(
        'p',
        { 'data-deviation': String(deviation) },
        `Largest distance between this curve and the original, over 1001 samples: ${deviation.toExponential(1)} — the same curve, up to rounding.`,
      ),
    ];
    if (state.k > 0) {
      const previous = polygons[polygons.length - 2];
      const m = previous.length - 1;
      nodes.push(
        formula(
          `\\text{last step } (N = ${m}):\\ Q_1 = \\tfrac{1}{${m + 1}}P_0 + \\tfrac{${m}}{${m + 1}}P_1 = ${texPoint(q[1], 3)}`,
          true,
        ),
      );
    }
    nodes.push(
      dataTable(
        'Distance from polygon to curve',
        ['Degree', 'max |Qi − P(i/N)|'],
        h(
          'tbody',
          {},
          polygons.map((polygon, j) =>
            h(
              'tr',
              { class: j === state.k ? 'current' : '' },
              h('td', {}, String(polygon.length - 1)),
              h('td', {}, controlPolygonGap(polygon).toFixed(4)),
            ),
          ),
        ),
      ),
      h(
        'p',
        { class: 'note' },
        'The gap between each control point and the curve point at the matching parameter shrinks about like 1/N: the polygon converges to the curve, slowly.',
      ),
    );
    return nodes;
  },
};
