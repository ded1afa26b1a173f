import type { Point, Preset } from '../../app/lesson';
import {
  type ExperimentId,
  LECTURE_CUBIC,
  type MapKind,
  type PropertiesState,
  stepCount,
} from './state';

/** A scene: the experiment and the figure set up for it, shown whole (the clicker opens it at step 0). */
const experiment = (
  id: string,
  label: string,
  x: ExperimentId,
  p: Point[],
  extra: Partial<PropertiesState> = {},
): Preset<PropertiesState> => ({
  id,
  label,
  apply: (s) => {
    const next = { ...s, x, p, q: [], t: 0.3, r: 1, ...extra };
    return { ...next, k: stepCount(next) };
  },
});

/** Twelve control points on a gentle wave: the long polygon of Figure 6. */
const WAVE: Point[] = Array.from({ length: 12 }, (_, i) => [
  i,
  Math.round(10 * Math.sin(i * 0.7) + 10) / 10,
]);
const WAVE_MOVED: Point[] = WAVE.map((q, i) => (i === 5 ? [q[0], q[1] + 2] : q));

const affinePreset = (id: string, label: string, m: MapKind) =>
  experiment(id, label, 'affine', LECTURE_CUBIC, { m, t: 0.4 });

/** One preset per experiment, numbered as the notes number the properties. */
export const PRESETS: Preset<PropertiesState>[] = [
  experiment('ends', '1 End tangents', 'ends', LECTURE_CUBIC),
  experiment('hull', '2 Convex hull', 'hull', [
    [0, 0],
    [1, 3],
    [3, 3.5],
    [2.5, 1],
    [5, 2],
    [6, 0],
  ]),
  experiment('local', '3 No local control', 'local', WAVE_MOVED, { q: WAVE, t: 0.45 }),
  experiment(
    'repeat',
    '4 Repeated point',
    'repeat',
    [
      [0, 0],
      [1, 3],
      [4, 3],
      [5, 0],
    ],
    { r: 1 },
  ),
  experiment('closed', '4 Closed curve', 'closed', [
    [0, 0],
    [-1, 3],
    [2, 4.5],
    [5, 3],
    [4, 0],
  ]),
  experiment('elevate', '5 Raise the degree', 'elevate', LECTURE_CUBIC),
  experiment('split', '6 Subdivision', 'split', LECTURE_CUBIC, { t: 0.5 }),
  affinePreset('affine', '7 Affine map', 'shear'),
  affinePreset('perspective', '7 Perspective map', 'perspective'),
  experiment('inflection', '8 Inflection', 'cubic', [
    [0, 0],
    [1.5, 3],
    [2.5, -1],
    [4, 2],
  ]),
  experiment(
    'loop',
    '8 Self-intersection',
    'cubic',
    [
      [0, 0],
      [5, 3],
      [-1, 3],
      [4, 0],
    ],
    { t: 0.5 },
  ),
  experiment('hermite', '9 Hermite form', 'hermite', LECTURE_CUBIC, { t: 0.4 }),
];
