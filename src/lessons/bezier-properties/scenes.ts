import type { ScriptedScene } from '../../kit/lesson';
import type { Point } from '../../math';
import type { PropertiesModel, Reveal } from './model';
import { SCRIPTS } from './scripts';
import { type ExperimentId, ARCH_CUBIC, type MapKind, type PropertiesState } from './state';

export interface PropertiesScene extends ScriptedScene<PropertiesState, PropertiesModel, Reveal> {
  /** The experiment the scene sets up: its steps are that experiment's. */
  experiment: ExperimentId;
}

/** A scene: the experiment and the figure set up for it, shown whole (the clicker opens it at step 0). */
const scene = (
  id: string,
  label: string,
  experiment: ExperimentId,
  points: Point[],
  extra: Partial<PropertiesState> = {},
): PropertiesScene => ({
  id,
  label,
  experiment,
  script: SCRIPTS[experiment],
  setup: (s) => {
    const next = { ...s, experiment, points, before: [], t: 0.3, repeated: 1, ...extra };
    return { ...next, step: SCRIPTS[experiment].lastStep(next) };
  },
});

/** Twelve control points on a gentle wave: the long polygon of Figure 6. */
const WAVE: Point[] = Array.from({ length: 12 }, (_, i) => [
  i,
  Math.round(10 * Math.sin(i * 0.7) + 10) / 10,
]);
const WAVE_MOVED: Point[] = WAVE.map((q, i) => (i === 5 ? [q[0], q[1] + 2] : q));

const affineScene = (id: string, label: string, map: MapKind) =>
  scene(id, label, 'affine', ARCH_CUBIC, { map, t: 0.4 });

/** One scene per experiment (two for maps and for cubics), numbered as the notes number the properties. */
export const SCENES: PropertiesScene[] = [
  scene('ends', '1 End tangents', 'ends', ARCH_CUBIC),
  scene('hull', '2 Convex hull', 'hull', [
    [0, 0],
    [1, 3],
    [3, 3.5],
    [2.5, 1],
    [5, 2],
    [6, 0],
  ]),
  scene('local', '3 No local control', 'local', WAVE_MOVED, { before: WAVE, t: 0.45 }),
  scene(
    'repeat',
    '4 Repeated point',
    'repeat',
    [
      [0, 0],
      [1, 3],
      [4, 3],
      [5, 0],
    ],
    { repeated: 1 },
  ),
  scene('closed', '4 Closed curve', 'closed', [
    [0, 0],
    [-1, 3],
    [2, 4.5],
    [5, 3],
    [4, 0],
  ]),
  scene('elevate', '5 Raise the degree', 'elevate', ARCH_CUBIC),
  scene('split', '6 Subdivision', 'split', ARCH_CUBIC, { t: 0.5 }),
  affineScene('affine', '7 Affine map', 'shear'),
  affineScene('perspective', '7 Perspective map', 'perspective'),
  scene('inflection', '8 Inflection', 'cubic', [
    [0, 0],
    [1.5, 3],
    [2.5, -1],
    [4, 2],
  ]),
  scene(
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
  scene('hermite', '9 Hermite form', 'hermite', ARCH_CUBIC, { t: 0.4 }),
  // Property 1 again, at every t: the whole derivative (#20).
  scene('hodograph', '1 Derivative curve', 'hodograph', ARCH_CUBIC),
];

/** The scene a state is in: the first that sets up its experiment (maps and cubics share their steps). */
export const sceneOf = (state: PropertiesState): string =>
  SCENES.find((s) => s.experiment === state.experiment)!.id;
