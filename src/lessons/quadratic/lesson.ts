import { defineLesson, type Point } from '../../app/lesson';
import { quadraticFigure } from './figure';
import { type QuadraticModel, derive } from './model';
import { quadraticPanel } from './panel';
import { MU_MAX, MU_MIN, type QuadraticState, STEP_TITLES, schema } from './state';

const preset = (id: string, label: string, p: Point[], step: number, mu = 0.5) => ({
  id,
  label,
  apply: (s: QuadraticState): QuadraticState => ({ ...s, p, step, mu }),
});

export default defineLesson<QuadraticState, QuadraticModel>({
  slug: 'quadratic',
  schema,
  derive,
  figures: [quadraticFigure],
  parameter: { key: 'mu', label: 'μ₁', min: MU_MIN, max: MU_MAX, step: 0.01 },
  steps: {
    key: 'step',
    count: () => STEP_TITLES.length - 1,
    describe: (_, k) => `${k}: ${STEP_TITLES[k]}`,
  },
  scenes: [
    preset(
      'figure-1',
      'Figure 1: a parabola',
      [
        [0, 1],
        [2, 3],
        [4, 2],
      ],
      0,
    ),
    preset(
      'same-x',
      'Two equal x',
      [
        [1, 0],
        [1, 2.5],
        [3.5, 1.5],
      ],
      0,
    ),
    preset(
      'backwards',
      'Going backwards',
      [
        [0, 0],
        [4, 2],
        [2, 3.5],
      ],
      0,
    ),
    preset(
      'figure-2',
      'Figure 2: the family',
      [
        [0, 0],
        [1, 2],
        [4, 1],
      ],
      2,
    ),
    preset(
      'uneven',
      'Uneven spacing',
      [
        [0, 0],
        [0.6, 1],
        [5, 1.5],
      ],
      3,
    ),
  ],
  panel: quadraticPanel,
});
