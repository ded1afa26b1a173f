import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'blending',
  title: 'A curve as a blend of its control points',
  summary:
    'Bernstein blending functions: the weights of every control point at μ, and why they sum to 1.',
  group: 'bezier',
  order: 2,
  load: () => import('./lesson').then((m) => m.default),
});
