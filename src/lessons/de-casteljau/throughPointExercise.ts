import { type ExerciseSpec, random } from '../../kit/exercise';
import { pointWords, sub, words } from '../../kit/format';
import { type Point, bernstein, bezierPoint, distance, subtract } from '../../math';
import { arch, walked } from './exerciseSetup';
import type { DeCasteljauState } from './state';

// The exercise that shapes the curve: move one inner point until P(t) lands
// on a marked point X, placed where the drag stays on the figure.

/** P(t) lands on X, a shown distance from where it is now: far enough to need a real move. */
const TARGET_DISTANCES = [0.5, 0.6, 0.7];
const TARGET_DIRECTIONS = [0, 45, 90, 135, 180, 225, 270, 315];
/** How far Pₖ may end up outside the polygon's box, so a drag to it stays on the figure. */
const MARGIN = 0.3;

/** X and the polygon with Pₖ moved so that P(t) = X, for one direction and distance of X. */
function targetFor(p: readonly Point[], t: number, k: number, degrees: number, reach: number) {
  const now = bezierPoint(p, t);
  const angle = (degrees * Math.PI) / 180;
  // One decimal, so the student reads X off the grid.
  const target = [now[0] + reach * Math.cos(angle), now[1] + reach * Math.sin(angle)].map(
    (v) => Math.round(10 * v) / 10,
  );
  // P(t) moves by W(3, k, t) times Pₖ's move: Pₖ goes the gap divided by that weight.
  const weight = bernstein(3, k, t);
  const moved = p.map((q, i) => (i === k ? q.map((v, d) => v + (target[d] - now[d]) / weight) : q));
  return { target, moved, weight };
}

/** Inside the polygon's box, grown by MARGIN. */
const inBox = (p: readonly Point[], q: Point) =>
  [0, 1].every((d) => {
    const values = p.map((point) => point[d]);
    return q[d] >= Math.min(...values) - MARGIN && q[d] <= Math.max(...values) + MARGIN;
  });

/** Move one inner point until the curve passes through X at the given t. */
export const throughPoint: ExerciseSpec<DeCasteljauState> = {
  id: 'through-point',
  title: 'Make the curve pass through X',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const p = arch(r, 3);
    const t = r.pick([0.4, 0.5, 0.6]);
    const k = r.pick([1, 2]);
    const candidates = TARGET_DIRECTIONS.flatMap((degrees) =>
      TARGET_DISTANCES.map((reach) => targetFor(p, t, k, degrees, reach)),
    );
    const fitting = candidates.filter(({ moved }) => inBox(p, moved[k]));
    const { target, moved, weight } = r.pick(fitting.length > 0 ? fitting : candidates);
    const tolerance = 0.08;
    const name = `P${sub(k)}`;
    const check = (state: DeCasteljauState) => {
      if (state.p.length !== 4)
        return {
          correct: false,
          message: `Keep the four control points P₀ … P₃ (there are ${state.p.length} now).`,
        };
      const strayed = state.p.findIndex((q, i) => i !== k && distance(q, p[i]) > 1e-9);
      if (strayed >= 0)
        return {
          correct: false,
          message: `Move only ${name}: P${sub(strayed)} belongs at ${pointWords(p[strayed])}.`,
        };
      const at = bezierPoint(state.p, t);
      const off = distance(at, target);
      const where = `P(${words(t)}) is at ${pointWords(at)}, ${words(off)} from X = ${pointWords(target)}`;
      if (off <= tolerance) return { correct: true, message: `Correct: ${where}.` };
      const needed = subtract(target, at).map((v) => v / weight);
      const slider =
        state.t === t
          ? ''
          : ` (the check reads t = ${words(t)}; the slider is at ${words(state.t)})`;
      return {
        correct: false,
        message: `Not yet: ${where}${slider}. P(${words(t)}) follows ${name} with the weight W(3, ${k}, ${words(t)}) = ${words(weight)}, so move ${name} by about ${pointWords(needed)}.`,
      };
    };
    return {
      state: walked(defaults, p, t),
      prompt: `Move only ${name} so that the curve passes through X = ${pointWords(target)} at t = ${words(t)}, within ${words(tolerance)}.`,
      task: { kind: 'construct', check, solution: walked(defaults, moved, t) },
      working: walked(defaults, moved, t),
      marks: [{ figure: 'construction', at: target, label: 'X' }],
    };
  },
};
