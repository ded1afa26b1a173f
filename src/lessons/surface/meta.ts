import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'surface',
  title: 'Bicubic Bézier patches',
  summary:
    'From curves to surfaces: 16 control points in space, the patch built from four row curves, its matrix form, weights and normals.',
  group: 'surfaces',
  order: 1,
  load: () => import('./lesson').then((m) => m.default),
});
