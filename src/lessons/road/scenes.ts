import type { Point, Preset } from '../../app/lesson';
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

/** A preset sets up villages (and what to look at); the script opens it at step 0. */
const preset = (
  id: string,
  label: string,
  change: (s: RoadState) => Partial<RoadState>,
): Preset<RoadState> => ({
  id,
  label,
  apply: (current) => {
    const next = { ...current, ...change(current) };
    return { ...next, s: Math.min(next.s, next.v.length - 1), step: 0 };
  },
});

/**
 * Villages shown with the natural spline, whatever was on before: a preset
 * sets up its whole figure (a ring road through a valley's villages, left
 * over from the lake preset, would only look broken).
 */
const villages = (v: Point[]) => () => ({ v, road: 'natural' as const, overlay: false });

export const presets: Preset<RoadState>[] = [
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
];
