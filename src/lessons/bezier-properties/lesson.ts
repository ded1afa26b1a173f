import { defineLesson } from '../../app/lesson';
import { propertiesFigure } from './figure';
import { propertiesPanel } from './panel';
import {
  type ExperimentId,
  LECTURE_CUBIC,
  type MapKind,
  type PropertiesState,
  normalize,
  schema,
  stepCount,
} from './state';

type Points = [number, number][];

const points = (list: readonly (readonly number[])[]): Points => list.map((q) => [q[0], q[1]]);

/** A preset: the experiment and the figure set up for it. */
const experiment = (
  id: string,
  label: string,
  x: ExperimentId,
  p: Points,
  extra: Partial<PropertiesState> = {},
) => ({
  id,
  label,
  apply: (s: PropertiesState): PropertiesState => ({
    ...s,
    x,
    p,
    q: [],
    t: 0.3,
    k: 0,
    r: 1,
    ...extra,
  }),
});

/** Twelve control points on a gentle wave: the long polygon of Figure 6. */
const WAVE: Points = Array.from({ length: 12 }, (_, i) => [
  i,
  Math.round(10 * Math.sin(i * 0.7) + 10) / 10,
]);
const WAVE_MOVED: Points = WAVE.map((q, i) => (i === 5 ? [q[0], q[1] + 2] : q));

const affinePreset = (id: string, label: string, m: MapKind) =>
  experiment(id, label, 'affine', points(LECTURE_CUBIC), { m, t: 0.4 });

export const bezierProperties = defineLesson<PropertiesState>({
  slug: 'bezier-properties',
  title: 'What a Bézier curve can and cannot do',
  summary:
    'Nine short experiments: end tangents, convex hull, no local control, degree elevation, subdivision, affine maps and more.',
  group: 'bezier',
  schema,
  figures: [propertiesFigure],
  parameter: { key: 't', label: 't', min: 0, max: 1, step: 0.01 },
  steps: {
    key: 'k',
    count: stepCount,
    describe(state, k) {
      switch (state.x) {
        case 'elevate':
          return k === 0
            ? `Degree ${state.p.length - 1}`
            : `Degree ${state.p.length - 1} → ${state.p.length - 1 + k}`;
        case 'split':
          return `${k} split${k === 1 ? '' : 's'}: ${2 ** k} piece${k === 0 ? '' : 's'}`;
        case 'repeat':
          return `P${state.r} × ${k + 1}`;
        default:
          return '';
      }
    },
  },
  presets: [
    experiment('ends', '1 End tangents', 'ends', points(LECTURE_CUBIC)),
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
      { k: 2, r: 1 },
    ),
    experiment('closed', '4 Closed curve', 'closed', [
      [0, 0],
      [-1, 3],
      [2, 4.5],
      [5, 3],
      [4, 0],
    ]),
    experiment('elevate', '5 Raise the degree', 'elevate', points(LECTURE_CUBIC)),
    experiment('split', '6 Subdivision', 'split', points(LECTURE_CUBIC), { t: 0.5, k: 1 }),
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
    experiment('hermite', '9 Hermite form', 'hermite', points(LECTURE_CUBIC), { t: 0.4 }),
  ],
  normalize,
  panel: propertiesPanel,
});
