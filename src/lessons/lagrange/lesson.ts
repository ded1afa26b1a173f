import { defineLesson, type Point } from '../../app/lesson';
import { basisFigure } from './basisFigure';
import { curveFigure } from './figure';
import { type LagrangeModel, derive } from './model';
import { lagrangePanel } from './panel';
import { describeStep, stepFormula } from './script';
import {
  DEFAULT_POINTS,
  type LagrangeState,
  RUNGE_POINTS,
  type Spacing,
  schema,
  stepCount,
} from './state';

const preset = (
  id: string,
  label: string,
  p: Point[],
  options: { spacing?: Spacing; spline?: boolean; t?: number } = {},
) => ({
  id,
  label,
  apply: (s: LagrangeState): LagrangeState => ({
    ...s,
    p,
    spacing: options.spacing ?? 'uniform',
    spline: options.spline ?? false,
    t: options.t ?? 0.4,
  }),
});

export default defineLesson<LagrangeState, LagrangeModel>({
  slug: 'lagrange',
  schema,
  derive,
  figures: [curveFigure, basisFigure],
  layout: 'column',
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  steps: { key: 'step', count: stepCount, describe: describeStep, formula: stepFormula },
  scenes: [
    preset('five', 'Five points', DEFAULT_POINTS),
    preset(
      'uneven',
      'Uneven spacing',
      [
        [0, 0],
        [0.5, 0.8],
        [1, 1],
        [5, 1.5],
        [6, 0],
      ],
      { spacing: 'uniform' },
    ),
    preset('runge', 'Runge: 11 equally spaced points on a bump', RUNGE_POINTS, { t: 0.05 }),
    preset('runge-spline', 'Runge vs a cubic spline', RUNGE_POINTS, { spline: true, t: 0.05 }),
    preset(
      'line',
      'Two points: a line',
      [
        [0, 0],
        [3, 2],
      ],
      { t: 0.5 },
    ),
  ],
  panel: lagrangePanel,
});
