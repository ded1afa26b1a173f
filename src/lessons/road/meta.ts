import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'road',
  title: 'A road through the villages',
  summary:
    'How should a road run through a number of villages? Straight lines, quadratics, Hermite pieces, natural, clamped and closed splines, side by side.',
  group: 'splines',
  order: 1,
  load: () => import('./lesson').then((m) => m.default),
});
