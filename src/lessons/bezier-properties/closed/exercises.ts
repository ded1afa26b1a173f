import {
  type ExerciseSpec,
  type Random,
  type Verdict,
  pointTask,
  random,
} from '../../../kit/exercise';
import { pointWords, sub, words } from '../../../kit/format';
import {
  type Point,
  bernsteinBasis,
  bezierDerivative,
  bezierPoint,
  distance,
  signedAngle,
} from '../../../math';
import { opened } from '../exerciseSetup';
import { SCRIPTS } from '../scripts';
import type { PropertiesState } from '../state';

// The two exercises on property 4, a closed curve: a point of it with P₀
// listed twice, and P₁ moved until the curve closes without a corner.

/** Three or four points round a loop (anticlockwise from the bottom), P₀ to be repeated at the end. */
function ring(r: Random, count: 3 | 4): Point[] {
  if (count === 3)
    return [
      [r.int(0, 2), 0],
      [r.int(4, 5), r.int(1, 3)],
      [r.int(0, 1), r.int(3, 4)],
    ];
  return [
    [r.int(1, 3), 0],
    [r.int(4, 6), r.int(1, 2)],
    [r.int(2, 4), r.int(3, 4)],
    [r.int(0, 1), r.int(1, 2)],
  ];
}

/** Property 4, a closed curve: P₀ listed again at the end; where is P(t)? */
export const closedPoint: ExerciseSpec<PropertiesState> = {
  id: 'closed-point',
  title: 'A point of the closed curve',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const points = ring(r, r.pick([3, 4] as const));
    const t = r.pick([0.25, 0.5, 0.75]);
    const n = points.length;
    const closed = [...points, points[0]];
    const answer = bezierPoint(closed, t);
    const tolerance = 0.25;
    const weights = bernsteinBasis(n, t);
    const hint = `P₀ is listed twice, so it weighs W(${n}, 0, t) + W(${n}, ${n}, t) = ${words(weights[0] + weights[n])} at t = ${words(t)}; the others weigh ${weights
      .slice(1, n)
      .map((w) => words(w))
      .join(', ')}, and P(t) is their weighted sum.`;
    return {
      state: opened(defaults, 'closed', { points, t }, (s) => SCRIPTS.closed.stepOf(s, 'polygon')),
      prompt: `P₀ is listed again at the end, P${sub(n)} = P₀, to close the curve: where is P(${words(t)})? Tap your guess; within ${words(tolerance)} of the point counts.`,
      task: pointTask('experiment', answer, tolerance, hint),
      working: opened(defaults, 'closed', { points, t }, 'last'),
    };
  },
};

/** How far P′(0) and P′(1) may differ: N times a tenth of a unit of P₁'s position. */
const C1_SLACK = 0.1;

/**
 * Property 4 again: the closed curve is smooth at P₀ only if it arrives as it
 * leaves. Move P₁ until P′(0) = N(P₁ − P₀) equals P′(1) = N(P₀ − Pₙ₋₁): C¹.
 */
export const closedSmooth: ExerciseSpec<PropertiesState> = {
  id: 'closed-smooth',
  title: 'Close the curve without a corner',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    // P₀ at the bottom, the last point level with it on the left: P₁ belongs level on the right.
    const p0: Point = [r.int(2, 3), 0];
    const last: Point = [r.int(0, 1), 0];
    const mirror: Point = [2 * p0[0] - last[0], 0];
    const points: Point[] = [
      p0,
      [mirror[0] + r.int(0, 1), r.int(1, 2)],
      [r.int(2, 4), r.int(3, 4)],
      last,
    ];
    const n = points.length;
    const tolerance = n * C1_SLACK;
    const check = (s: PropertiesState): Verdict => {
      if (s.points.length !== n)
        return {
          correct: false,
          message: `Keep the ${n} control points P₀ … P${sub(n - 1)} (there are ${s.points.length} now).`,
        };
      const strayed = s.points.findIndex((q, i) => i !== 1 && distance(q, points[i]) > 1e-9);
      if (strayed >= 0)
        return {
          correct: false,
          message: `Move only P₁: P${sub(strayed)} belongs at ${pointWords(points[strayed])}.`,
        };
      const hodograph = bezierDerivative([...s.points, s.points[0]]);
      const leaving = hodograph[0];
      const arriving = hodograph[hodograph.length - 1];
      const tangents = `P′(0) = ${pointWords(leaving)} and P′(1) = ${pointWords(arriving)}`;
      if (distance(leaving, arriving) <= tolerance)
        return { correct: true, message: `Correct: ${tangents}, so the curve is C¹ at P₀.` };
      const corner = Math.abs((signedAngle(arriving, leaving) * 180) / Math.PI);
      const need = `C¹ at P₀ needs P₁ − P₀ = P₀ − P${sub(n - 1)}`;
      return {
        correct: false,
        message:
          corner < 1
            ? `Not yet: ${tangents} point the same way (smooth to the eye), but their lengths differ; ${need}.`
            : `Not yet: ${tangents} meet at a corner of ${corner.toFixed(1)}°; ${need}.`,
      };
    };
    const state = opened(defaults, 'closed', { points }, 'last');
    const solution = { ...state, points: points.map((q, i) => (i === 1 ? mirror : q)) };
    return {
      state,
      prompt: `Move only P₁ so that the closed curve is C¹ at P₀ = P${sub(n)}: it leaves P₀ with the very velocity it arrives with, P′(0) = P′(1), within ${words(tolerance)}.`,
      task: { kind: 'construct', check, solution },
      working: solution,
    };
  },
};
