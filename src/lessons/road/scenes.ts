import type { Point } from '../../app/lesson';
import type { SceneSpec } from '../../kit/lesson';
import { defaultsOf } from '../../app/urlState';
import { seededRandom } from '../../math/seededRandom';
import { CURVES } from './roads';
import { LECTURE_VILLAGES, type RoadState, roundPoint, schema } from './state';

/**
 * `count` villages up a winding valley: hairpin bends climbing a hillside, each
 * village a little off the valley floor. Deterministic for a given count.
 */
export function valleyVillages(count: number, seed = 6): Point[] {
  const random = seededRandom(seed);
  const villages: Point[] = [];
  const bends = Math.max(1, Math.round(count / 80));
  for (let i = 0; i < count; i++) {
    const u = count === 1 ? 0 : i / (count - 1);
    const x = 70 + 62 * Math.sin(Math.PI * (bends * u - 0.5));
    const y = 100 * u + 3 * Math.sin(9 * Math.PI * u);
    villages.push(roundPoint([x + (random() - 0.5) * 1.6, y + (random() - 0.5) * 1.6]));
  }
  return villages;
}

/** A scene sets up villages (and what to look at); the clicker opens it at step 0. */
const scene = (
  id: string,
  label: string,
  change: (s: RoadState) => Partial<RoadState>,
): SceneSpec<RoadState> => ({
  id,
  label,
  setup: (current) => {
    const next = { ...current, ...change(current) };
    return { ...next, pBar: Math.min(next.pBar, next.villages.length - 1), step: 0 };
  },
});

/**
 * Villages shown with the natural spline, whatever was on before: a scene
 * sets up its whole figure (a ring road through a valley's villages, left
 * over from the lake scene, would only look broken).
 */
const naturalThrough = (villages: Point[]) => () => ({
  villages,
  road: 'natural' as const,
  overlay: false,
});

/** The lesson's scenes, in teaching order. */
export const scenes: SceneSpec<RoadState>[] = [
  // Back to the lesson as it opens: the lecture's villages, the natural spline, nothing else.
  scene('lecture', 'Lecture villages', () => defaultsOf(schema)),
  scene('compare', 'Every answer at once', (s) => ({
    villages: s.villages.length > 12 ? LECTURE_VILLAGES : s.villages,
    overlay: true,
    compare: CURVES.map((_, i) => i),
  })),
  scene('swing', 'Quadratics swing', () => ({
    villages: LECTURE_VILLAGES,
    road: 'quadratic',
    overlay: false,
    quadraticGradient: [10, 40],
  })),
  scene('ring', 'Villages round a lake', () => ({
    villages: [
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
  scene(
    'two',
    'Two villages',
    naturalThrough([
      [0, 0],
      [60, 25],
    ]),
  ),
  scene(
    'line',
    'Villages in a line',
    naturalThrough([
      [0, 0],
      [20, 8],
      [30, 12],
      [70, 28],
      [100, 40],
    ]),
  ),
  scene(
    'same',
    'Two villages on one spot',
    naturalThrough([
      [0, 0],
      [20, 16],
      [42, 10],
      [42, 10],
      [78, 26],
      [92, 44],
    ]),
  ),
  scene('valley50', 'Valley: 50 villages', naturalThrough(valleyVillages(50))),
  scene('valley500', 'Valley: 500 villages', naturalThrough(valleyVillages(500))),
];
