import { h, setText } from '../../../app/dom';
import type { ExperimentPanel } from '../experimentPanel';
import type { ModelOf } from '../model';

function shapeOf(m: ModelOf<'hull'>): string {
  const corners = m.hull.length;
  const within = m.controls.length - corners;
  if (corners === 1)
    return 'All control points coincide: the hull is a single point, and the "curve" is that point.';
  if (corners === 2)
    return 'All control points lie on one line: the hull is a segment, and the curve runs along it (possibly back and forth).';
  return `The hull has ${corners} corners; ${within} control point${within === 1 ? ' lies' : 's lie'} inside it or on an edge.`;
}

export const hullPanel: ExperimentPanel<ModelOf<'hull'>> = {
  number: 2,
  title: 'Convex hull',
  sentence:
    'Every point of the curve is an average of the control points with non-negative weights, so the curve never leaves their convex hull. Drag the points and try to make it escape.',
  build() {
    const verdict = h('p', {});
    const shape = h('p', {});
    const nodes = [verdict, shape];
    return {
      update(m) {
        const { inside, total } = m;
        setText(
          verdict,
          inside === total
            ? `All ${total} sampled curve points lie in the hull.`
            : `${total - inside} of ${total} samples lie outside the hull: that would contradict the theorem — please report it.`,
        );
        setText(shape, shapeOf(m));
        return nodes;
      },
    };
  },
};
