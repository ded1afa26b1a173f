import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'quadratic',
  title: 'A curve through three points: parabola or parametric quadratic',
  summary:
    'The parabola y(x) through three points fails when the points turn back; a parametric quadratic needs a choice of μ₁.',
  group: 'interpolation',
  order: 1,
  load: () => import('./lesson').then((m) => m.default),
});
