import { defineLesson, type Point } from '../../app/lesson';
import { curveFigure } from './curveFigure';
import { type BlendingModel, derive } from './model';
import { blendingPanel } from './panel';
import { plotFigure } from './plotFigure';
import { describeStep, stepFormula } from './script';
import { type BlendingState, type Comparison, LECTURE_CUBIC, schema, stepCount } from './state';

const preset = (id: string, label: string, p: Point[], mu: number, b: Comparison = 'none') => ({
  id,
  label,
  apply: (s: BlendingState): BlendingState => ({ ...s, p, mu, b }),
});

export default defineLesson<BlendingState, BlendingModel>({
  slug: 'blending',
  schema,
  derive,
  figures: [curveFigure, plotFigure],
  layout: 'row',
  parameter: { key: 'mu', label: 'μ', min: 0, max: 1, step: 0.01 },
  steps: { key: 'step', count: stepCount, describe: describeStep, formula: stepFormula },
  scenes: [
    preset('cubic', 'Lecture cubic, μ = 0.5', LECTURE_CUBIC, 0.5),
    preset(
      'linear',
      'N = 1: a straight line',
      [
        [0, 0],
        [4, 2],
      ],
      0.25,
    ),
    preset(
      'quadratic',
      'N = 2',
      [
        [0, 0],
        [2, 3],
        [4, 0],
      ],
      0.3,
    ),
    preset(
      'degree6',
      'N = 6',
      [
        [0, 0],
        [0.5, 2.5],
        [2, 3],
        [3, 1],
        [4, 3],
        [5.5, 2.5],
        [6, 0],
      ],
      0.3,
    ),
    preset(
      'degree10',
      'N = 10',
      Array.from({ length: 11 }, (_, i) => [i / 2, i % 2 === 0 ? 0 : 3]),
      0.5,
    ),
    preset('hermite', 'Compare: Hermite', LECTURE_CUBIC, 0.3, 'hermite'),
    preset('bspline', 'Compare: B-spline', LECTURE_CUBIC, 0.3, 'bspline'),
    preset(
      'lagrange',
      'Compare: Lagrange',
      [
        [0, 0],
        [1, 0],
        [2, 0],
        [3, 1.5],
        [4, 3],
        [5, 3],
        [6, 3],
      ],
      0.1,
      'lagrange',
    ),
  ],
  panel: blendingPanel,
});
