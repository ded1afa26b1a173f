import { h, setText } from '../../../app/dom';
import { LiveFormula, SLOT, texNumber } from '../../../render/formula';
import { type ExperimentPanel, arrangements } from '../experimentPanel';
import { smallNumber } from '../../../kit/format';
import type { ModelOf } from '../model';
import { CENTRE, SHIFT } from './maps';

const row = `${SLOT} & ${SLOT} & ${SLOT}`;
const MATRIX = `\\begin{pmatrix}x'w\\\\ y'w\\\\ w\\end{pmatrix} = \\begin{pmatrix}${row}\\\\${row}\\\\${row}\\end{pmatrix}\\begin{pmatrix}x\\\\ y\\\\ 1\\end{pmatrix}`;

/** The rational form, with one slot per weight. */
const rationalShape = (count: number) =>
  `\\text{rational: } \\frac{\\sum_i w_i W(N,i,t)\\,P_i'}{\\sum_i w_i W(N,i,t)}\\ \\text{ with } w_i = ${Array.from({ length: count }, () => SLOT).join(',\\,')}`;

export const affinePanel: ExperimentPanel<ModelOf<'affine'>> = {
  number: 7,
  title: 'Affine invariance',
  sentence:
    'Mapping the control points and then drawing the curve gives the same as mapping the curve itself, for every affine map; for a perspective map it does not, which is what rational curves (NURBS) repair.',
  build() {
    const intro = h(
      'p',
      {},
      `The map, in coordinates centred at (${CENTRE.join(', ')}) (its image is drawn ${SHIFT} units to the right):`,
    );
    const matrix = new LiveFormula(true);
    const vanishing = h(
      'p',
      {},
      'A control point is on or beyond the vanishing line of this perspective map (w ≤ 0): its image is at infinity or on the far side, so no image is drawn. Move the points back to the right.',
    );
    const why = h('p', { class: 'note' });
    const deviation = h('p', {});
    const affineNote = h(
      'p',
      { class: 'note' },
      'The last row is (0, 0, 1), so w = 1 everywhere: the map is affine, the weights W(N, i, t) sum to 1 and survive it. The solid and dashed images coincide, and so do the two points at t.',
    );
    const divides = h('p', { class: 'note' });
    const rational = new LiveFormula(true);
    const repaired = h('p', {});
    const show = arrangements();
    return {
      update(m) {
        matrix.set(
          MATRIX,
          m.linear.flat().map((v) => texNumber(v, 3)),
        );
        const images = m.images;
        if (!images.ok) {
          setText(why, images.why);
          return show('none', () => [intro, matrix.element, vanishing, why]);
        }
        const d = images.distance;
        deviation.dataset.mapDeviation = String(d);
        setText(
          deviation,
          `Largest distance between the two images at equal t: ${d < 1e-9 ? smallNumber(d) : d.toFixed(4)}${d < 1e-9 ? ' — they agree, up to rounding.' : `, at t = ${images.at.toFixed(3)}: they differ.`}`,
        );
        // An affine map leaves nothing to repair.
        if (images.rationalDistance === null)
          return show('affine', () => [intro, matrix.element, deviation, affineNote]);
        const ws = images.weights;
        const [low, high] = images.weightRange;
        setText(
          divides,
          `Here w runs from ${low.toFixed(2)} to ${high.toFixed(2)} over the control points: the map divides by w, and dividing does not commute with averaging. The ring (map of P(t)) and the dot (curve of the mapped points at t) separate.`,
        );
        rational.set(
          rationalShape(ws.length),
          ws.map((w) => texNumber(w, 2)),
        );
        repaired.dataset.rationalDeviation = String(images.rationalDistance);
        setText(
          repaired,
          `Giving each mapped control point its w as a weight (a rational Bézier curve, the simplest NURBS) reproduces the map of the curve: largest distance ${smallNumber(images.rationalDistance)}.`,
        );
        return show('perspective', () => [
          intro,
          matrix.element,
          deviation,
          divides,
          rational.element,
          repaired,
        ]);
      },
    };
  },
};
