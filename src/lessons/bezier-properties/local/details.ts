import { h, setText } from '../../../app/dom';
import { LiveFormula, SLOT, texNumber } from '../../../render/formula';
import { type ExperimentPanel, arrangements } from '../experimentPanel';
import type { ModelOf } from '../model';
import { gestures } from '../../../kit/gestures';

/** Only Pi moved, so the curve moved by W(N, i, t)·ΔPi: largest at t = i/N. */
const boundShape = (n: number, i: number) =>
  `\\begin{aligned}P_{\\text{after}}(t) - P_{\\text{before}}(t) &= W(${n},${i},t)\\,\\Delta P_{${i}}\\\\ \\max_t W(${n},${i},t) &= W\\bigl(${n},${i},\\tfrac{${i}}{${n}}\\bigr) = ${SLOT}\\\\ \\max_t |P_{\\text{after}} - P_{\\text{before}}| &= ${SLOT} \\times ${SLOT} = ${SLOT}\\end{aligned}`;

export const localPanel: ExperimentPanel<ModelOf<'local'>> = {
  number: 3,
  title: 'No local control',
  sentence:
    'Moving one control point moves the whole curve, but an inner point of a long polygon has a small weight everywhere, so the curve barely follows it.',
  build() {
    const unmoved = h(
      'p',
      {},
      `The dashed "before" curve is the current one. Take an inner control point, ${gestures().move}, and compare.`,
    );
    const displacement = h('p', {});
    const bound = new LiveFormula(true);
    const share = h('p', { class: 'note' });
    const movedList = h('p', { class: 'note' });
    const show = arrangements();
    return {
      update(m) {
        const { at, distance } = m.largest;
        setText(
          displacement,
          `Largest displacement of the curve: ${distance.toFixed(4)}, at t = ${at.toFixed(3)} (dashed: before; the orange arrow shows it).`,
        );
        if (m.moved.length === 0) return show('unmoved', () => [unmoved]);
        if (!m.single) {
          setText(movedList, `Points moved: ${m.moved.map((i) => `P${i}`).join(', ')}.`);
          return show('several', () => [displacement, movedList]);
        }
        const { index: i, shift, peak } = m.single;
        bound.set(boundShape(m.n, i), [
          texNumber(peak, 4),
          texNumber(peak, 4),
          texNumber(shift, 3),
          texNumber(peak * shift, 4),
        ]);
        setText(
          share,
          `P${i} moved by ${shift.toFixed(3)}, the curve by at most ${m.single.percent.toFixed(1)}% of that. Every point of the curve moved (there is no local control), yet none by much: the weight of P${i} is never more than ${peak.toFixed(3)}.`,
        );
        return show('one', () => [displacement, bound.element, share]);
      },
    };
  },
};
