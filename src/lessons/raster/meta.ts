import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'raster',
  title: 'From a curve to pixels',
  summary:
    'Plot a spline as line segments: uniform against adaptive flattening, subdivision stepped, then Bresenham pixels and anti-aliasing.',
  group: 'surfaces',
  order: 2,
  load: () => import('./lesson').then((m) => m.default),
});
