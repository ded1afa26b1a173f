import { defineLesson, type Point } from '../../app/lesson';
import { constructionFigure } from './figure';
import { type DeCasteljauModel, derive } from './model';
import { deCasteljauPanel } from './panel';
import { type DeCasteljauState, LECTURE_CUBIC, degree, schema } from './state';

const preset = (id: string, label: string, p: Point[], t = 0.4) => ({
  id,
  label,
  apply: (s: DeCasteljauState): DeCasteljauState => ({ ...s, p, t, step: p.length - 1 }),
});

export default defineLesson<DeCasteljauState, DeCasteljauModel>({
  slug: 'de-casteljau',
  schema,
  derive,
  figures: [constructionFigure],
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  steps: {
    key: 'step',
    count: degree,
    describe: (state, k) =>
      k === degree(state)
        ? `Level ${k} of ${degree(state)}: P(t)`
        : `Level ${k} of ${degree(state)}`,
  },
  scenes: [
    preset('cubic', 'Lecture cubic', LECTURE_CUBIC),
    preset(
      'quadratic',
      'Quadratic',
      [
        [0, 0],
        [2, 3],
        [4, 0],
      ],
      0.5,
    ),
    preset(
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
    preset(
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
