import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'bezier-properties',
  title: 'What a Bézier curve can and cannot do',
  summary:
    'Nine short experiments: end tangents, convex hull, no local control, degree elevation, subdivision, affine maps and more.',
  group: 'bezier',
  order: 3,
  load: () => import('./lesson').then((m) => m.default),
});
