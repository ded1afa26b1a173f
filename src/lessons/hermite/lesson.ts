import { defineLesson, type Point } from '../../app/lesson';
import { basisFigure } from './basisFigure';
import { curveFigure } from './figure';
import { type HermiteModel, derive } from './model';
import { hermitePanel } from './panel';
import {
  type GradientMode,
  type HermiteState,
  ONE_PATCH,
  ONE_PATCH_GRADIENTS,
  normalize,
  schema,
  stepCount,
} from './state';
import { describeStep, stepFormula } from './script';

const SEVERAL: Point[] = [
  [0, 0],
  [2, 2],
  [5, 1.5],
  [6.5, -1],
  [9, 0.5],
];
const SEVERAL_GRADIENTS: Point[] = [
  [2, 3],
  [3, 0],
  [2, -2],
  [3, 0],
  [2, 2],
];

const preset = (
  id: string,
  label: string,
  p: Point[],
  d: Point[],
  options: { mode?: GradientMode; bezier?: boolean; patch?: number } = {},
) => ({
  id,
  label,
  apply: (s: HermiteState): HermiteState => ({
    ...s,
    p,
    d,
    mode: options.mode ?? 'hand',
    bezier: options.bezier ?? false,
    patch: options.patch ?? 0,
    mu: 0.3,
  }),
});

export default defineLesson<HermiteState, HermiteModel>({
  slug: 'hermite',
  schema,
  derive,
  normalize,
  figures: [curveFigure, basisFigure],
  layout: 'column',
  parameter: { key: 'mu', label: 'μ', min: 0, max: 1, step: 0.01 },
  steps: { key: 'step', count: stepCount, describe: describeStep, formula: stepFormula },
  scenes: [
    preset('one', 'One patch', ONE_PATCH, ONE_PATCH_GRADIENTS),
    preset('long', 'Long gradients: a loop', ONE_PATCH, [
      [15, 12],
      [15, -12],
    ]),
    preset('several', 'Several points, by hand', SEVERAL, SEVERAL_GRADIENTS, { patch: 1 }),
    preset('catmull-rom', 'Several points, Catmull-Rom', SEVERAL, SEVERAL_GRADIENTS, {
      mode: 'catmull-rom',
      patch: 1,
    }),
    preset('bezier', 'As a Bézier curve', ONE_PATCH, ONE_PATCH_GRADIENTS, { bezier: true }),
  ],
  panel: hermitePanel,
});
