import type { Point } from '../../math';
import { defineLesson } from '../../kit/lesson';
import { basisFigure } from './basisFigure';
import { exercises } from './exercises';
import { curveFigure } from './figure';
import { derive } from './model';
import { hermitePanel } from './panel';
import { bezierScript, construction } from './script';
import {
  type GradientMode,
  type HermiteState,
  ONE_PATCH,
  ONE_PATCH_GRADIENTS,
  normalize,
  schema,
} from './state';

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

/**
 * A scene: its points and gradients, at μ = 0.3 (the clicker opens it at step
 * 0). The Bézier view walks its own steps and shows the curve's figure alone.
 */
const scene = (
  id: string,
  label: string,
  points: Point[],
  handGradients: Point[],
  options: { mode?: GradientMode; bezier?: boolean; patch?: number } = {},
) => ({
  id,
  label,
  ...(options.bezier ? { script: bezierScript, figures: ['patches'] } : { script: construction }),
  setup: (s: HermiteState): HermiteState => ({
    ...s,
    points,
    handGradients,
    mode: options.mode ?? 'hand',
    bezier: options.bezier ?? false,
    patch: options.patch ?? 0,
    mu: 0.3,
  }),
});

export default defineLesson({
  slug: 'hermite',
  letter: 'mu',
  schema,
  step: 'step',
  script: construction,
  // The scenes of one patch or several share the construction; the Bézier view has its own steps.
  sceneOf: (state) => (state.bezier ? 'bezier' : 'one'),
  derive,
  normalize,
  figures: [curveFigure, basisFigure],
  layout: 'column',
  // A patch taller than wide (long gradients) is drawn larger with its weights beside it.
  tallLayout: { row: ['patches', 'basis'] },
  parameter: { key: 'mu', label: 'μ', min: 0, max: 1, step: 0.01 },
  scenes: [
    scene('one', 'One patch', ONE_PATCH, ONE_PATCH_GRADIENTS),
    scene('long', 'Long gradients: a loop', ONE_PATCH, [
      [15, 12],
      [15, -12],
    ]),
    scene('several', 'Several points, by hand', SEVERAL, SEVERAL_GRADIENTS, { patch: 1 }),
    scene('catmull-rom', 'Several points, Catmull-Rom', SEVERAL, SEVERAL_GRADIENTS, {
      mode: 'catmull-rom',
      patch: 1,
    }),
    scene('bezier', 'As a Bézier curve', ONE_PATCH, ONE_PATCH_GRADIENTS, { bezier: true }),
  ],
  panel: hermitePanel,
  exercises,
});
