import { defineLesson, type Point2 } from '../../app/lesson';
import { basisFigure } from './basisFigure';
import { curveFigure } from './figure';
import { hermitePanel } from './panel';
import { type GradientMode, type HermiteState, normalize, patchCount, schema } from './state';

const SEVERAL: Point2[] = [
  [0, 0],
  [2, 2],
  [5, 1.5],
  [6.5, -1],
  [9, 0.5],
];
const SEVERAL_GRADIENTS: Point2[] = [
  [2, 3],
  [3, 0],
  [2, -2],
  [3, 0],
  [2, 2],
];

const preset = (
  id: string,
  label: string,
  p: Point2[],
  d: Point2[],
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

const ONE: Point2[] = [
  [0, 0],
  [4, 0],
];

export const hermite = defineLesson<HermiteState>({
  slug: 'hermite',
  title: 'Cubic Hermite patches: points and gradients',
  summary: 'A cubic from two end points and two end gradients; chained, it is smooth at the joins.',
  group: 'interpolation',
  schema,
  normalize,
  figures: [curveFigure, basisFigure],
  layout: 'column',
  parameter: { key: 'mu', label: 'μ', min: 0, max: 1, step: 0.01 },
  steps: {
    key: 'patch',
    count: (state) => patchCount(state) - 1,
    describe: (state, k) => `Patch ${k + 1} of ${patchCount(state)}`,
  },
  presets: [
    preset('one', 'One patch', ONE, [
      [3, 4.5],
      [3, -4.5],
    ]),
    preset('long', 'Long gradients: a loop', ONE, [
      [15, 12],
      [15, -12],
    ]),
    preset('several', 'Several points, by hand', SEVERAL, SEVERAL_GRADIENTS, { patch: 1 }),
    preset('catmull-rom', 'Several points, Catmull-Rom', SEVERAL, SEVERAL_GRADIENTS, {
      mode: 'catmull-rom',
      patch: 1,
    }),
    preset(
      'bezier',
      'As a Bézier curve',
      ONE,
      [
        [3, 4.5],
        [3, -4.5],
      ],
      { bezier: true },
    ),
  ],
  panel: hermitePanel,
});
