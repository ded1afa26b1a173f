import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'hermite',
  title: 'Cubic Hermite patches: points and gradients',
  summary: 'A cubic from two end points and two end gradients; chained, it is smooth at the joins.',
  group: 'interpolation',
  order: 3,
  load: () => import('./lesson').then((m) => m.default),
});
