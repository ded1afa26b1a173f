import type { Point } from '../../app/lesson';
import type { ScriptedScene } from '../../kit/lesson';
import { defaultsOf } from '../../app/urlState';
import { seededRandom } from '../../math/seededRandom';
import { derivationScript } from './derivationScript';
import { globalScript } from './globalScript';
import type { RoadModel } from './model';
import { CURVES } from './roads';
import type { Reveal } from './script';
import { SIX_VILLAGES, type RoadState, roundPoint, schema } from './state';
import type { RoadView } from './view';

type RoadScene = ScriptedScene<RoadState, RoadModel, Reveal>;

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
): RoadScene => ({
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
const naturalThrough =
  (villages: Point[], view: RoadView = 'road') =>
  () => ({
    villages,
    road: 'natural' as const,
    view,
  });

/** The lesson's scenes, in teaching order. */
export const scenes: RoadScene[] = [
  // Back to the lesson as it opens: the six villages, the natural spline, nothing else.
  // (The id is the scene's old name: links keep opening it.)
  scene('lecture', 'Six villages inland', () => defaultsOf(schema)),
  scene('compare', 'Every answer at once', (s) => ({
    villages: s.villages.length > 12 ? SIX_VILLAGES : s.villages,
    view: 'compare',
    compare: CURVES.map((_, i) => i),
  })),
  scene('swing', 'Quadratics swing', () => ({
    villages: SIX_VILLAGES,
    road: 'quadratic',
    view: 'road',
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
    view: 'road',
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
  {
    // At the default p̄ (2.4), so the join worked at is P2 whatever the scene before left.
    ...scene('derivation', 'The system, derived at a join', () => ({
      ...naturalThrough(SIX_VILLAGES, 'derivation')(),
      pBar: schema.pBar.default,
    })),
    script: derivationScript,
  },
  {
    ...scene('global', 'Global, and affine-invariant', naturalThrough(SIX_VILLAGES, 'global')),
    script: globalScript,
  },
];

/** The scene a state is in, where its view says so (the others share the road's steps). */
export function sceneOf(state: RoadState): string {
  if (state.view === 'compare') return 'compare';
  if (state.view === 'road') return 'lecture';
  return state.view;
}
