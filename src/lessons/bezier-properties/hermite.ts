import { h } from '../../app/dom';
import {
  add,
  bezierPoint,
  bezierToHermite,
  bezierToPowerBasis,
  hermitePoint,
  sampleBezier,
  sampledDeviation,
} from '../../math';
import { formula, texPoint } from '../../render/formula';
import { type Experiment, drawBezier, drawMarked, drawPolygon, texT } from './experiment';

const SAMPLES = 200;

function hermiteSamples(p: readonly (readonly number[])[]): number[] {
  const [x0, d0, x1, d1] = bezierToHermite(p);
  const flat: number[] = [];
  for (let k = 0; k <= SAMPLES; k++) flat.push(...hermitePoint(x0, d0, x1, d1, k / SAMPLES));
  return flat;
}

export const hermite: Experiment = {
  id: 'hermite',
  title: 'Bézier cubics are cubic spline patches',
  sentence:
    'A cubic Bézier curve is the Hermite patch with end points P0, P3 and end tangents 3(P1 − P0), 3(P3 − P2): the same polynomial, a0 + a1μ + a2μ² + a3μ³, written with other data.',
  extent(state) {
    const [x0, d0, x1, d1] = bezierToHermite(state.p);
    return [add(x0, d0), add(x1, d1)];
  },
  draw(painter, state, info) {
    const theme = painter.theme;
    const p = state.p;
    const [x0, d0, x1, d1] = bezierToHermite(p);
    drawPolygon(painter, p);
    drawBezier(painter, p, { color: painter.color(0), width: theme.sizes.curve * 2.2 });
    painter.polylineFlat(hermiteSamples(p), {
      color: painter.color(1),
      width: theme.sizes.curve * 0.8,
      dash: [10, 6],
    });
    painter.arrow(x0, add(x0, d0), { color: painter.color(1), width: theme.sizes.line * 1.3 });
    painter.arrow(x1, add(x1, d1), { color: painter.color(1), width: theme.sizes.line * 1.3 });
    if (!info.thumbnail) {
      painter.label('3(P_1 − P_0)', add(x0, d0), {
        dx: 6,
        dy: -theme.sizes.label * 0.6,
        color: painter.color(1),
        halo: true,
        bold: true,
      });
      painter.label('3(P_3 − P_2)', add(x1, d1), {
        dx: 6,
        dy: -theme.sizes.label * 0.6,
        color: painter.color(1),
        halo: true,
        bold: true,
      });
    }
    drawMarked(painter, bezierPoint(p, state.t), 'P(t)', info);
  },
  explain(state, api) {
    const p = state.p;
    const palette = api.theme().palette;
    const [a0, a1, a2, a3] = bezierToPowerBasis(p);
    const [x0, d0, x1, d1] = bezierToHermite(p);
    const deviation = sampledDeviation(sampleBezier(p, SAMPLES), hermiteSamples(p)).distance;
    const t = state.t;
    return [
      h('p', {}, h('strong', {}, 'Power form (equation 11 of the notes)')),
      formula(
        `\\begin{aligned}a_0 &= P_0 = ${texPoint(a0)}\\\\ a_1 &= 3(P_1 - P_0) = ${texPoint(a1)}\\\\ a_2 &= 3(P_2 - 2P_1 + P_0) = ${texPoint(a2)}\\\\ a_3 &= P_3 - 3P_2 + 3P_1 - P_0 = ${texPoint(a3)}\\end{aligned}`,
        true,
      ),
      h('p', {}, h('strong', {}, 'Hermite form: end points and end tangents')),
      formula(
        `\\begin{aligned}x_0 &= P_0 = ${texPoint(x0)}, & x_0' &= 3(P_1 - P_0) = ${texPoint(d0)}\\\\ x_1 &= P_3 = ${texPoint(x1)}, & x_1' &= 3(P_3 - P_2) = ${texPoint(d1)}\\end{aligned}`,
        true,
      ),
      formula(
        `P(${texT(t)}) = H_0 x_0 + H_1 x_1 + H_2 x_0' + H_3 x_1' = ${texPoint(hermitePoint(x0, d0, x1, d1, t), 4)}`,
        true,
      ),
      h(
        'p',
        {},
        h('span', { class: 'swatch', style: `background:${palette[0]}` }),
        'Bézier form (wide)  ',
        h('span', { class: 'swatch', style: `background:${palette[1]}` }),
        'Hermite form (dashed): ',
        `largest distance between them over ${SAMPLES + 1} samples ${deviation.toExponential(1)} — one curve.`,
      ),
    ];
  },
};
