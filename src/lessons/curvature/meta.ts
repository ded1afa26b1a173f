import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'curvature',
  title: 'Curvature and the Frenet frame',
  summary:
    'Tangent, normal, curvature and the osculating circle of a Bézier curve; the Frenet frame and torsion in space; arc length against parameter.',
  group: 'splines',
  order: 4,
  load: () => import('./lesson').then((m) => m.default),
});
