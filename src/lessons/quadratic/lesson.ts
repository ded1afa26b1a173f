import type { Point } from '../../math';
import { defineLesson } from '../../kit/lesson';
import { exercises } from './exercises';
import { quadraticFigure } from './figure';
import { derive } from './model';
import { quadraticPanel } from './panel';
import { construction } from './script';
import { DEFAULT_POINTS, MU_MAX, MU_MIN, type QuadraticState, schema } from './state';

/** A scene: its three points and μ1, shown to the end (the clicker opens it at step 0). */
const scene = (id: string, label: string, points: Point[], mu = 0.5) => ({
  id,
  label,
  setup: (s: QuadraticState): QuadraticState => {
    const next = { ...s, points, mu };
    return { ...next, step: construction.lastStep(next) };
  },
});

export default defineLesson({
  slug: 'quadratic',
  letter: 'mu',
  schema,
  step: 'step',
  script: construction,
  derive,
  figures: [quadraticFigure],
  parameter: { key: 'mu', label: 'μ₁', min: MU_MIN, max: MU_MAX, step: 0.01 },
  // In the lecture's order: a parabola, two ways it fails, the family, the rules.
  scenes: [
    scene('figure-1', 'Figure 1: a parabola', DEFAULT_POINTS),
    scene('same-x', 'Two equal x', [
      [1, 0],
      [1, 2.5],
      [3.5, 1.5],
    ]),
    scene('backwards', 'Going backwards', [
      [0, 0],
      [4, 2],
      [2, 3.5],
    ]),
    scene('figure-2', 'Figure 2: the family', [
      [0, 0],
      [1, 2],
      [4, 1],
    ]),
    scene('uneven', 'Uneven spacing', [
      [0, 0],
      [0.6, 1],
      [5, 1.5],
    ]),
  ],
  panel: quadraticPanel,
  exercises,
});
