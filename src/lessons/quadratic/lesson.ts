import { defineLesson, type Point } from '../../app/lesson';
import { quadraticFigure } from './figure';
import { type QuadraticModel, derive } from './model';
import { quadraticPanel } from './panel';
import { describeStep, stepFormula } from './script';
import { DEFAULT_POINTS, LAST_STEP, MU_MAX, MU_MIN, type QuadraticState, schema } from './state';

/** A scene: its three points, shown to the end (the clicker opens it at step 0). */
const scene = (id: string, label: string, p: Point[], mu = 0.5) => ({
  id,
  label,
  apply: (s: QuadraticState): QuadraticState => ({ ...s, p, step: LAST_STEP, mu }),
});

export default defineLesson<QuadraticState, QuadraticModel>({
  slug: 'quadratic',
  schema,
  derive,
  figures: [quadraticFigure],
  parameter: { key: 'mu', label: 'μ₁', min: MU_MIN, max: MU_MAX, step: 0.01 },
  steps: {
    key: 'step',
    count: () => LAST_STEP,
    describe: describeStep,
    formula: stepFormula,
  },
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
});
