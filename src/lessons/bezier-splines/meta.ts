import { defineMeta } from '../../app/meta';

export default defineMeta({
  slug: 'bezier-splines',
  title: 'Joining Bézier pieces: splines',
  summary:
    'C¹ quadratic and C² cubic splines through points, the linear system behind C², a continuity inspector for every joint, and Catmull-Rom.',
  group: 'splines',
  order: 2,
  load: () => import('./lesson').then((m) => m.default),
});
