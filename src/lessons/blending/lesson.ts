import { defineLesson } from '../../app/lesson';
import { curveFigure } from './curveFigure';
import { blendingPanel } from './panel';
import { plotFigure } from './plotFigure';
import { type BlendingState, type Comparison, LECTURE_CUBIC, schema } from './state';

const preset = (
  id: string,
  label: string,
  p: [number, number][],
  mu: number,
  b: Comparison = 'none',
) => ({
  id,
  label,
  apply: (s: BlendingState): BlendingState => ({ ...s, p, mu, b }),
});

const cubic = () => LECTURE_CUBIC.map((q): [number, number] => [q[0], q[1]]);

export const blending = defineLesson<BlendingState>({
  slug: 'blending',
  title: 'A curve as a blend of its control points',
  summary:
    'Bernstein blending functions: the weights of every control point at μ, and why they sum to 1.',
  group: 'bezier',
  schema,
  figures: [curveFigure, plotFigure],
  layout: 'row',
  parameter: { key: 'mu', label: 'μ', min: 0, max: 1, step: 0.01 },
  presets: [
    preset('cubic', 'Lecture cubic, μ = 0.5', cubic(), 0.5),
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
      Array.from({ length: 11 }, (_, i): [number, number] => [i / 2, i % 2 === 0 ? 0 : 3]),
      0.5,
    ),
    preset('hermite', 'Compare: Hermite', cubic(), 0.3, 'hermite'),
    preset('bspline', 'Compare: B-spline', cubic(), 0.3, 'bspline'),
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
