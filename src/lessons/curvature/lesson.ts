import { defineLesson, type Point } from '../../app/lesson';
import { cubicInflections } from '../../math';
import { curveFigure } from './curveFigure';
import { stepFormula } from './formulas';
import { type CurvatureModel, derive } from './model';
import { curvaturePanel } from './panel';
import { plotFigure } from './plotFigure';
import { hermiteGradients } from './sources';
import { spaceFigure } from './spaceFigure';
import {
  type CurvatureState,
  LECTURE_CUBIC,
  TWISTED_CUBIC,
  describeStep,
  schema,
  stepCount,
} from './state';

/** An S-shaped cubic: symmetric, so it inflects at t = 1/2. */
const S_CURVE: Point[] = [
  [0, 0],
  [1.5, 2.5],
  [2.5, -2.5],
  [4, 0],
];
/** P2 − P1 = P0 − P3 makes P′(1/2) = 0: a cusp. */
const CUSP: Point[] = [
  [0, 0],
  [4, 3],
  [0, 3],
  [4, 0],
];
/** A curve that is slow at its start and fast at its end, so equal t is not equal length. */
const UNEVEN: Point[] = [
  [0, 0],
  [0.3, 2.5],
  [1.2, 2.8],
  [5, 0],
];

/** Five points with a bend each way: a spline through them has joins to look at. */
const SPLINE_POINTS: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2.5],
  [4.5, 0.5],
  [6, 2],
];

const plane = (id: string, label: string, p: Point[], t: number) => ({
  id,
  label,
  apply: (s: CurvatureState): CurvatureState => ({ ...s, part: 'plane', src: 'bezier', p, t }),
});

const spline = (id: string, label: string, src: 'natural' | 'catmull-rom') => ({
  id,
  label,
  apply: (s: CurvatureState): CurvatureState => ({
    ...s,
    part: 'plane',
    src,
    p: SPLINE_POINTS,
    t: 0.45,
  }),
});

/** Arc length is worked on one Bézier curve; Hermite gradients come one per point. */
function normalize(state: CurvatureState): { state: CurvatureState; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  if (next.part === 'arc' && next.src !== 'bezier') {
    next = { ...next, src: 'bezier' };
    issues.push('Arc length is worked on one Bézier curve: its control points are the points P.');
  }
  if (next.src === 'hermite' && next.d.length !== next.p.length) {
    issues.push(
      `d: ${next.d.length} gradients for ${next.p.length} points; where one is missing Catmull-Rom's is used, extra ones are left out.`,
    );
    next = { ...next, d: hermiteGradients(next.p, next.d) };
  }
  return { state: next, issues };
}

export default defineLesson<CurvatureState, CurvatureModel>({
  slug: 'curvature',
  schema,
  derive,
  figures: [curveFigure, plotFigure, spaceFigure],
  layout: { column: [{ row: ['curve', 'space'] }, 'plot'], weights: [3, 2] },
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  steps: { key: 'step', count: stepCount, describe: describeStep, formula: stepFormula },
  scenes: [
    plane('plane', 'Curvature of a plane curve', LECTURE_CUBIC, 0.3),
    plane('inflection', 'An inflection: κ = 0', S_CURVE, cubicInflections(S_CURVE)[0]),
    plane('cusp', 'A cusp: speed 0', CUSP, 0.5),
    {
      id: 'helix',
      label: 'The Frenet frame of a helix',
      apply: (s) => ({ ...s, part: 'space', curve: 'helix', a: 1, b: 0.25, t: 0.3 }),
    },
    {
      id: 'twisted',
      label: 'A space cubic: the frame flips',
      apply: (s) => ({ ...s, part: 'space', curve: 'bezier', q: TWISTED_CUBIC, t: 0.3 }),
    },
    {
      id: 'arc',
      label: 'Arc length against parameter',
      apply: (s) => ({ ...s, part: 'arc', src: 'bezier', p: UNEVEN, n: 8, t: 0.5 }),
    },
    spline('natural', 'A natural spline: κ is continuous at its C² joins', 'natural'),
    spline('catmull', 'A Catmull-Rom spline: κ jumps at its C¹ joins', 'catmull-rom'),
  ],
  normalize,
  panel: curvaturePanel,
});
