import { h } from '../../../app/dom';
import { LiveFormula, SLOT } from '../../../render/formula';
import { texT } from '../../../kit/format';
import { type ExperimentPanel, coords, slotPoint } from '../experimentPanel';
import { smallNumber } from '../../../kit/format';
import type { ModelOf } from '../model';
import { SAMPLES } from './model';

const P = slotPoint();
const POWER = `\\begin{aligned}a_0 &= P_0 = ${P}\\\\ a_1 &= 3(P_1 - P_0) = ${P}\\\\ a_2 &= 3(P_2 - 2P_1 + P_0) = ${P}\\\\ a_3 &= P_3 - 3P_2 + 3P_1 - P_0 = ${P}\\end{aligned}`;
const HERMITE = `\\begin{aligned}x_0 &= P_0 = ${P}, & x_0' &= 3(P_1 - P_0) = ${P}\\\\ x_1 &= P_3 = ${P}, & x_1' &= 3(P_3 - P_2) = ${P}\\end{aligned}`;
const AT_T = `P(${SLOT}) = H_0 x_0 + H_1 x_1 + H_2 x_0' + H_3 x_1' = ${P}`;

export const hermitePanel: ExperimentPanel<ModelOf<'hermite'>> = {
  number: 9,
  title: 'Bézier cubics are cubic spline patches',
  sentence:
    'A cubic Bézier curve is the Hermite patch with end points P0, P3 and end tangents 3(P1 − P0), 3(P3 − P2): the same polynomial, a0 + a1t + a2t² + a3t³, written with other data.',
  build(api) {
    const power = new LiveFormula(true);
    const hermite = new LiveFormula(true);
    const atT = new LiveFormula(true);
    const bezierSwatch = h('span', { class: 'swatch' });
    const hermiteSwatch = h('span', { class: 'swatch' });
    const agreement = document.createTextNode('');
    const nodes = [
      h('p', {}, h('strong', {}, 'Power form: P(t) = a0 + a1t + a2t² + a3t³')),
      power.element,
      h('p', {}, h('strong', {}, 'Hermite form: end points and end tangents')),
      hermite.element,
      atT.element,
      h(
        'p',
        {},
        bezierSwatch,
        'Bézier form (wide)  ',
        hermiteSwatch,
        'Hermite form (dashed): ',
        agreement,
      ),
    ];
    return {
      update(m) {
        const palette = api.theme().palette;
        bezierSwatch.style.background = palette[0];
        hermiteSwatch.style.background = palette[2];
        power.set(
          POWER,
          m.power.flatMap((a) => coords(a)),
        );
        hermite.set(
          HERMITE,
          [m.x0, m.d0, m.x1, m.d1].flatMap((v) => coords(v)),
        );
        atT.set(AT_T, [texT(m.state.t), ...coords(m.hermiteAtT, 4)]);
        agreement.data = `largest distance between them over ${SAMPLES + 1} samples ${smallNumber(m.deviation)} — one curve.`;
        return nodes;
      },
    };
  },
};
