import type { Point } from '../../math';
import { defineLesson } from '../../kit/lesson';
import { exercises } from './exercises';
import { constructionFigure } from './figure';
import { derive } from './model';
import { deCasteljauPanel } from './panel';
import { construction } from './script';
import { constructionTables } from './tables';
import { type DeCasteljauState, LECTURE_CUBIC, schema } from './state';

/** A scene: its control points and t, shown to the end (the clicker opens it at step 0). */
const scene = (id: string, label: string, p: Point[], t = 0.4) => ({
  id,
  label,
  setup: (s: DeCasteljauState): DeCasteljauState => {
    const next = { ...s, p, t, split: false };
    return { ...next, step: construction.lastStep(next) };
  },
});

export default defineLesson({
  slug: 'de-casteljau',
  schema,
  step: 'step',
  script: construction,
  derive,
  figures: [constructionFigure],
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
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
  tables: constructionTables,
  exercises,
});
