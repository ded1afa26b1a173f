import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'lagrange',
  title: 'One polynomial through n + 1 points: Lagrange interpolation',
  summary:
    'The Lagrange polynomial through any number of points, its basis, and why it wiggles (Runge).',
  group: 'interpolation',
  order: 2,
  load: () => import('./lesson').then((m) => m.default),
});
