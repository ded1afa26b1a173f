/**
 * The exercise on adaptive flattening's test: the flatness of a cubic, built
 * from its differences so that the bound is worked out by hand.
 */
import {
  type ExerciseSpec,
  type Mistake,
  type Random,
  checkNumbers,
  random,
} from '../../kit/exercise';
import type { Point } from '../../math';
import { listed, sceneState } from './exerciseSetup';
import { flatteningOf } from './geometry';
import type { RasterState } from './state';

/** The flatness is asked to two decimals. */
export const FLATNESS_TOLERANCE = 0.01;

/**
 * A cubic from its differences: P₁ − P₀ = v, Δ²P₀ = a, Δ²P₁ = b, so P₂ = 2v + a
 * and P₃ = 3v + 2a + b from P₀, moved to the middle of the raster. Neither is
 * zero, |a| and |b| differ by at least 1 and the larger is 3 or more, so the
 * flatness is 2.25 px or more (and at most 0.75·√50 ≈ 5.3 px).
 */
function cubicFromDifferences(r: Random): { points: Point[]; a: Point; b: Point } {
  for (;;) {
    const v: Point = [r.int(3, 5), r.int(-2, 2)];
    const a: Point = [r.int(-5, 5), r.int(-5, 5)];
    const b: Point = [r.int(-5, 5), r.int(-5, 5)];
    const [la, lb] = [Math.hypot(a[0], a[1]), Math.hypot(b[0], b[1])];
    if (Math.abs(la - lb) < 1 || Math.max(la, lb) < 3 || Math.min(la, lb) < 1) continue;
    const from0: Point[] = [
      [0, 0],
      v,
      [2 * v[0] + a[0], 2 * v[1] + a[1]],
      [3 * v[0] + 2 * a[0] + b[0], 3 * v[1] + 2 * a[1] + b[1]],
    ];
    const shift = [16, 12].map((centre, d) => {
      const values = from0.map((p) => p[d]);
      return centre - Math.round((Math.min(...values) + Math.max(...values)) / 2);
    });
    return { points: from0.map((p) => [p[0] + shift[0], p[1] + shift[1]]), a, b };
  }
}

/**
 * τ of the flatness exercise's working: below every flatness it poses (2.25 px
 * and up), above a quarter of each (5.3/4): the whole curve is split once, and
 * the first press of the subdivision visits it, its flatness in the formula.
 */
const FLATNESS_WORKING_TAU = 2;

export const flatness: ExerciseSpec<RasterState> = {
  id: 'flatness',
  title: 'How far can the curve be from its chord?',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const { points, a, b } = cubicFromDifferences(r);
    const [la, lb] = [Math.hypot(a[0], a[1]), Math.hypot(b[0], b[1])];
    const state = sceneState(defaults, 'subdivide', points, { tolerance: FLATNESS_WORKING_TAU });
    const answer = [flatteningOf(state).tree[0].flatness * state.zoom];
    const mistakes: Mistake[] = [
      {
        values: [Math.max(la, lb)],
        hint: 'That is max‖Δ²P‖ alone: multiply by n(n − 1)/8 = 3·2/8 for a cubic.',
      },
      {
        values: [(12 / 8) * Math.max(la, lb)],
        hint: 'n is the degree, 3 for four control points: n(n − 1)/8 = 6/8.',
      },
      {
        values: [(6 / 8) * Math.min(la, lb)],
        hint: 'Take the larger of the two second differences, ‖P₂ − 2P₁ + P₀‖ and ‖P₃ − 2P₂ + P₁‖.',
      },
      {
        values: [(6 / 8) * (la + lb)],
        hint: 'The bound takes the largest second difference, not their sum.',
      },
    ];
    return {
      state,
      prompt: `Adaptive flattening tests the cubic with control points ${listed(points)} against τ. What is its flatness n(n − 1)/8 · max‖Pᵢ₊₂ − 2Pᵢ₊₁ + Pᵢ‖ in pixels, to 2 decimals?`,
      task: {
        kind: 'number',
        fields: ['flatness (px)'],
        tolerance: FLATNESS_TOLERANCE,
        answer,
        check: (values) =>
          checkNumbers(
            values,
            answer,
            FLATNESS_TOLERANCE,
            'Work out both second differences P₂ − 2P₁ + P₀ and P₃ − 2P₂ + P₁, take the longer, and multiply by 3·2/8.',
            mistakes,
          ),
      },
      // The test, then the first piece visited, the whole curve, with its flatness against τ.
      working: state,
    };
  },
};
