import { defineLesson } from '../../kit/lesson';
import { curveFigure } from './curveFigure';
import { exercises } from './exercises';
import { derive } from './model';
import { curvaturePanel } from './panel';
import { plotFigure } from './plotFigure';
import { SCENES, sceneOf } from './scenes';
import { hermiteGradients } from './sources';
import { spaceFigure } from './spaceFigure';
import { type CurvatureState, schema } from './state';

/** Arc length is worked on one Bézier curve; Hermite gradients come one per point. */
function normalize(state: CurvatureState): { state: CurvatureState; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  if (next.part === 'arc' && next.source !== 'bezier') {
    next = { ...next, source: 'bezier' };
    issues.push('Arc length is worked on one Bézier curve: its control points are the points P.');
  }
  if (next.part === 'joins' && next.source !== 'natural') {
    next = { ...next, source: 'natural' };
    issues.push(
      'The joins are compared on the natural cubic spline through the points (and the Catmull-Rom spline of the same points).',
    );
  }
  const { points, gradients } = next;
  if (next.source === 'hermite' && gradients.length !== points.length) {
    issues.push(
      `d: ${gradients.length} gradients for ${points.length} points; where one is missing Catmull-Rom's is used, extra ones are left out.`,
    );
    next = { ...next, gradients: hermiteGradients(points, gradients) };
  }
  return { state: next, issues };
}

export default defineLesson({
  slug: 'curvature',
  letter: 't',
  schema,
  step: 'step',
  // The part (plane, space, arc length) says which steps a state walks.
  sceneOf,
  derive,
  figures: [curveFigure, plotFigure, spaceFigure],
  layout: { column: [{ row: ['curve', 'space'] }, 'plot'], weights: [3, 2] },
  // A curve taller than wide is drawn larger with the space view (as large as before) and κ beside it.
  tallLayout: { row: ['curve', { column: ['space', 'plot'], weights: [1.5, 1] }], weights: [1, 1] },
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  scenes: SCENES,
  normalize,
  panel: curvaturePanel,
  exercises,
});
