import type { Point } from '../../math';
import { defineLesson } from '../../kit/lesson';
import { curveFigure } from './curveFigure';
import { exercises } from './exercises';
import { derive } from './model';
import { blendingPanel } from './panel';
import { plotFigure } from './plotFigure';
import { bsplineScript, hermiteScript, lagrangeScript } from './compareScripts';
import { passesScript } from './passesScript';
import { lessonScript } from './script';
import { type BlendingState, type Comparison, LECTURE_CUBIC, schema } from './state';

/** A scene: its control points, μ and the basis compared with (the clicker opens it at step 0). */
const scene = (
  id: string,
  label: string,
  p: Point[],
  mu: number,
  comparison: Comparison = 'none',
) => ({
  id,
  label,
  setup: (s: BlendingState): BlendingState => ({ ...s, p, mu, comparison }),
});

export default defineLesson({
  slug: 'blending',
  letter: 'mu',
  schema,
  step: 'step',
  // Bernstein's steps (or the symmetry's); each Compare scene walks a script of its own.
  script: lessonScript,
  // The comparison chosen says which: the Compare scenes are named after theirs.
  sceneOf: (s) => s.comparison,
  derive,
  figures: [curveFigure, plotFigure],
  layout: 'row',
  parameter: { key: 'mu', label: 'μ', min: 0, max: 1, step: 0.01 },
  scenes: [
    scene('cubic', 'A cubic, μ = 0.5', LECTURE_CUBIC, 0.5),
    scene(
      'linear',
      'N = 1: a straight line',
      [
        [0, 0],
        [4, 2],
      ],
      0.25,
    ),
    scene(
      'quadratic',
      'N = 2',
      [
        [0, 0],
        [2, 3],
        [4, 0],
      ],
      0.3,
    ),
    scene(
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
    scene(
      'degree10',
      'N = 10',
      Array.from({ length: 11 }, (_, i) => [i / 2, i % 2 === 0 ? 0 : 3]),
      0.5,
    ),
    {
      ...scene('hermite', 'Compare: Hermite', LECTURE_CUBIC, 0.3, 'hermite'),
      script: hermiteScript,
    },
    {
      ...scene('bspline', 'Compare: B-spline', LECTURE_CUBIC, 0.3, 'bspline'),
      script: bsplineScript,
    },
    {
      ...scene(
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
      script: lagrangeScript,
    },
    {
      ...scene(
        'interpolating',
        'Interpolating or approximating',
        LECTURE_CUBIC,
        0.5,
        'interpolating',
      ),
      script: passesScript,
    },
  ],
  panel: blendingPanel,
  exercises,
});
