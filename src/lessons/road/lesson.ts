import { defineLesson } from '../../app/lesson';
import { defaultsOf } from '../../app/urlState';
import type { Point2 } from '../../app/lesson';
import { mapFigure } from './figure';
import { roadPanel } from './panel';
import { CURVES } from './roads';
import { describeStep } from './solve';
import {
  LECTURE_VILLAGES,
  type RoadState,
  normalize,
  schema,
  stepCount,
  valleyVillages,
} from './state';

/** A preset sets up villages (and what to look at); the whole solve is shown. */
const preset = (id: string, label: string, change: (s: RoadState) => Partial<RoadState>) => ({
  id,
  label,
  apply: (current: RoadState): RoadState => {
    const next = { ...current, ...change(current) };
    return { ...next, s: Math.min(next.s, next.v.length - 1), step: stepCount(next) };
  },
});

/**
 * Villages shown with the natural spline, whatever was on before: a preset
 * sets up its whole figure (a ring road through a valley's villages, left
 * over from the lake preset, would only look broken).
 */
const villages = (v: Point2[]) => () => ({ v, road: 'natural' as const, overlay: false });

export const road = defineLesson<RoadState>({
  slug: 'road',
  title: 'A road through the villages',
  summary:
    'How should a road run through a number of villages? Straight lines, quadratics, Hermite pieces, natural, clamped and closed splines, side by side.',
  group: 'splines',
  schema,
  figures: [mapFigure],
  steps: { key: 'step', count: stepCount, describe: describeStep },
  normalize,
  presets: [
    // Back to the lesson as it opens: the lecture's villages, the natural spline, nothing else.
    preset('lecture', 'Lecture villages', () => defaultsOf(schema)),
    preset('compare', 'Every answer at once', (s) => ({
      v: s.v.length > 12 ? LECTURE_VILLAGES : s.v,
      overlay: true,
      compare: CURVES.map((_, i) => i),
    })),
    preset('swing', 'Quadratics swing', () => ({
      v: LECTURE_VILLAGES,
      road: 'quadratic',
      overlay: false,
      q: [10, 40],
    })),
    preset('ring', 'Villages round a lake', () => ({
      v: [
        [0, 20],
        [18, 2],
        [46, 0],
        [70, 12],
        [74, 38],
        [50, 52],
        [22, 46],
      ],
      road: 'ring',
      overlay: false,
    })),
    preset(
      'two',
      'Two villages',
      villages([
        [0, 0],
        [60, 25],
      ]),
    ),
    preset(
      'line',
      'Villages in a line',
      villages([
        [0, 0],
        [20, 8],
        [30, 12],
        [70, 28],
        [100, 40],
      ]),
    ),
    preset(
      'same',
      'Two villages on one spot',
      villages([
        [0, 0],
        [20, 16],
        [42, 10],
        [42, 10],
        [78, 26],
        [92, 44],
      ]),
    ),
    preset('valley50', 'Valley: 50 villages', villages(valleyVillages(50))),
    preset('valley500', 'Valley: 500 villages', villages(valleyVillages(500))),
  ],
  panel: roadPanel,
});
