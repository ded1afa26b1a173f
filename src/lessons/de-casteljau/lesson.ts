import { defineLesson, type Point } from '../../app/lesson';
import { constructionFigure } from './figure';
import { type DeCasteljauModel, derive } from './model';
import { deCasteljauPanel } from './panel';
import { describeStep, stepFormula } from './script';
import { type DeCasteljauState, LECTURE_CUBIC, lastStep, schema } from './state';

/** A scene: its control points and t, shown to the end (the clicker opens it at step 0). */
const scene = (id: string, label: string, p: Point[], t = 0.4) => ({
  id,
  label,
  apply: (s: DeCasteljauState): DeCasteljauState => ({
    ...s,
    p,
    t,
    split: false,
    step: lastStep({ ...s, p }),
  }),
});

export default defineLesson<DeCasteljauState, DeCasteljauModel>({
  slug: 'de-casteljau',
  schema,
  derive,
  figures: [constructionFigure],
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  steps: { key: 'step', count: lastStep, describe: describeStep, formula: stepFormula },
  scenes: [
    scene('cubic', 'Lecture cubic', LECTURE_CUBIC),
    scene(
      'quadratic',
      'Quadratic',
      [
        [0, 0],
        [2, 3],
        [4, 0],
      ],
      0.5,
    ),
    scene(
      'loop',
      'Cubic with a loop',
      [
        [0, 0],
        [5, 3],
        [-1, 3],
        [4, 0],
      ],
      0.5,
    ),
    scene(
      'quintic',
      'Degree 5',
      [
        [0, 0],
        [0, 2],
        [2, 3],
        [4, 1],
        [5, 3],
        [6, 0],
      ],
      0.3,
    ),
  ],
  panel: deCasteljauPanel,
});
