import { defineLesson, type Point2 } from '../../app/lesson';
import { quadraticFigure } from './figure';
import { quadraticPanel } from './panel';
import { MU_MAX, MU_MIN, type QuadraticState, STEP_TITLES, schema } from './state';

const preset = (id: string, label: string, p: Point2[], step: number, mu = 0.5) => ({
  id,
  label,
  apply: (s: QuadraticState): QuadraticState => ({ ...s, p, step, mu }),
});

export const quadratic = defineLesson<QuadraticState>({
  slug: 'quadratic',
  title: 'A curve through three points: parabola or parametric quadratic',
  summary:
    'The parabola y(x) through three points fails when the points turn back; a parametric quadratic needs a choice of μ₁.',
  group: 'interpolation',
  schema,
  figures: [quadraticFigure],
  parameter: { key: 'mu', label: 'μ₁', min: MU_MIN, max: MU_MAX, step: 0.01 },
  steps: {
    key: 'step',
    count: () => STEP_TITLES.length - 1,
    describe: (_, k) => `${k}: ${STEP_TITLES[k]}`,
  },
  presets: [
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
