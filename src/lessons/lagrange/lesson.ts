import type { Point } from '../../math';
import { defineLesson } from '../../kit/lesson';
import { basisFigure } from './basisFigure';
import { exercises } from './exercises';
import { curveFigure } from './figure';
import { derive } from './model';
import { lagrangePanel } from './panel';
import { comparison, interpolation } from './script';
import { DEFAULT_POINTS, type LagrangeState, RUNGE_POINTS, type Spacing, schema } from './state';

/** A scene: its points, spacing, spline and t (the clicker opens it at step 0). */
const scene = (
  id: string,
  label: string,
  points: Point[],
  options: { spacing?: Spacing; spline?: boolean; t?: number } = {},
) => ({
  id,
  label,
  setup: (s: LagrangeState): LagrangeState => ({
    ...s,
    points,
    spacing: options.spacing ?? 'uniform',
    spline: options.spline ?? false,
    t: options.t ?? 0.4,
  }),
});

export default defineLesson({
  slug: 'lagrange',
  letter: 't',
  schema,
  step: 'step',
  script: interpolation,
  // With the spline switched on, a state walks the comparison's script, in whichever scene.
  sceneOf: (s) => (s.spline ? 'runge-spline' : 'five'),
  derive,
  figures: [curveFigure, basisFigure],
  layout: 'column',
  // A curve taller than wide (Runge's bell) is drawn larger with its basis beside it.
  tallLayout: { row: ['curve', 'basis'] },
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  scenes: [
    scene('five', 'Five points', DEFAULT_POINTS),
    scene(
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
    scene('runge', 'Runge: 11 equally spaced points on a bump', RUNGE_POINTS, { t: 0.05 }),
    {
      ...scene('runge-spline', 'Runge vs a cubic spline', RUNGE_POINTS, { spline: true, t: 0.05 }),
      script: comparison,
    },
    scene(
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
  exercises,
});
