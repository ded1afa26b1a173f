import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'de-casteljau',
  title: 'The de Casteljau construction',
  summary: 'Build a point of a Bézier curve by repeated linear interpolation, level by level.',
  group: 'bezier',
  order: 1,
  load: () => import('./lesson').then((m) => m.default),
});
