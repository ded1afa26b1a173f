import type { ScriptedScene } from '../../kit/lesson';
import type { Point } from '../../math';
import type { DeCasteljauModel } from './model';
import { ARCH_CUBIC, type DeCasteljauState, type Mode } from './state';
import { type Reveal, SCRIPTS } from './walks';

/** A scene: its control points, t and walk, shown to the end (the clicker opens it at step 0). */
const scene = (
  id: string,
  label: string,
  p: Point[],
  t: number,
  mode: Mode = 'construction',
): ScriptedScene<DeCasteljauState, DeCasteljauModel, Reveal> => ({
  id,
  label,
  script: SCRIPTS[mode],
  setup: (s) => {
    const next = { ...s, p, t, mode };
    return { ...next, step: SCRIPTS[mode].lastStep(next) };
  },
});

/** The scenes in teaching order; the two walks of the arch at t = 0.5 came last (#20). */
export const SCENES = [
  // Figure 5 of the lecture notes builds its point at μ ≈ 0.6.
  scene('cubic', 'Cubic at t = 0.6, as Figure 5', ARCH_CUBIC, 0.6),
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
  // The lecture slides' Example 4.18 asks where x(0.5) is: the arch's P(0.5), worked by hand.
  scene('pseudocode', 'Pseudocode: P(0.5) by hand', ARCH_CUBIC, 0.5, 'pseudocode'),
  scene('bernstein', 'Back to the Bernstein form', ARCH_CUBIC, 0.5, 'bernstein'),
];

/** The scene a state is in: its walk's (the construction's scenes share their steps). */
export const sceneOf = (state: DeCasteljauState): string =>
  state.mode === 'pseudocode' || state.mode === 'bernstein' ? state.mode : 'cubic';
