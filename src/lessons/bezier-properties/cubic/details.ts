import { h, setText } from '../../../app/dom';
import { LiveFormula, SLOT, formula } from '../../../render/formula';
import { texT } from '../../../kit/format';
import { type ExperimentPanel, arrangements, coords, slotPoint } from '../experimentPanel';
import type { ModelOf } from '../model';

const CROSSING = `P(${SLOT}) = P(${SLOT}) = ${slotPoint()}`;

export const cubicPanel: ExperimentPanel<ModelOf<'cubic'>> = {
  number: 8,
  title: 'Inflection and self-intersection',
  sentence:
    'A cubic can turn both ways (an inflection, where the curvature changes sign) or cross itself (a loop); where the control points are decides which, and at most two inflections or one loop fit in a cubic.',
  build(api) {
    const leftSwatch = h('span', { class: 'swatch' });
    const rightSwatch = h('span', { class: 'swatch' });
    const key = h(
      'p',
      {},
      leftSwatch,
      'turning left (curvature > 0)   ',
      rightSwatch,
      'turning right (curvature < 0)',
    );
    const kappa = formula("\\kappa(t) = \\frac{x'y'' - y'x''}{(x'^2 + y'^2)^{3/2}}", true);
    const curvature = h('p', {});
    const straight = h(
      'p',
      {},
      'All four control points lie on one line: the curve is straight, its curvature is zero everywhere, so it has neither inflection nor loop.',
    );
    const inflections = h('p', {});
    const crossing = new LiveFormula(true);
    const loop = h(
      'p',
      {},
      'The curve crosses itself: a loop. Along a loop the curve turns one way, so a loop and an inflection exclude each other on a cubic.',
    );
    const noLoop = h('p', {}, 'No self-intersection on [0, 1].');
    const cusp = h(
      'p',
      {},
      'Somewhere the speed is zero: a cusp, between a loop and an inflection.',
    );
    const show = arrangements();
    return {
      update(m) {
        const palette = api.theme().palette;
        leftSwatch.style.background = palette[0];
        rightSwatch.style.background = palette[2];
        const t = texT(m.state.t);
        setText(
          curvature,
          m.curvature === null
            ? `At t = ${t} the speed is zero (a cusp): the curvature is not defined there.`
            : `κ(${t}) = ${m.curvature.toFixed(4)}`,
        );
        if (m.straight) return show('straight', () => [key, kappa, curvature, straight]);
        const found = m.inflections.map((inflection) => inflection.t.toFixed(4));
        setText(
          inflections,
          found.length === 0
            ? 'No inflection on [0, 1]: the curve turns one way only.'
            : `Inflection${found.length > 1 ? 's' : ''} at t = ${found.join(' and ')}, where P′ × P″ = 0 and the curvature changes sign.`,
        );
        if (m.loop)
          crossing.set(CROSSING, [
            m.loop.t[0].toFixed(4),
            m.loop.t[1].toFixed(4),
            ...coords(m.loop.point, 3),
          ]);
        return show(`${m.loop !== null} ${m.cusp}`, () => [
          key,
          kappa,
          curvature,
          inflections,
          ...(m.loop ? [crossing.element, loop] : [noLoop]),
          ...(m.cusp ? [cusp] : []),
        ]);
      },
    };
  },
};
