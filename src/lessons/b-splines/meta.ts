import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'b-splines',
  title: 'B-splines and NURBS',
  summary:
    'The uniform cubic B-spline and its local control; knots, Cox–de Boor and repeated knots; conversions; NURBS and the exact circle.',
  group: 'splines',
  order: 3,
  load: () => import('./lesson').then((m) => m.default),
});
