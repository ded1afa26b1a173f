/**
 * The exercise that shapes a curve: a quadratic whose P₁ is dragged until
 * adaptive flattening draws it with exactly two segments.
 */
import { type ExerciseSpec, type Verdict, random } from '../../kit/exercise';
import { pointWords, words } from '../../kit/format';
import { type Point, distance, flatteningTree } from '../../math';
import { sceneState } from './exerciseSetup';
import type { RasterState } from './state';

/** The tolerance τ of the construction, in pixels. */
export const SPLIT_TOLERANCE = 0.5;

/**
 * Directions from the chord's middle to P₁, 3 to 3.2 px long and steep (the
 * chord is nearly level): P₁ off the line P₀P₂, over its middle.
 */
const DIRECTIONS: Point[] = [
  [0, 3],
  [0, -3],
  [1, 3],
  [-1, 3],
  [1, -3],
  [-1, -3],
];

/** The segments adaptive flattening makes at τ, and the flatness of the whole curve and of its halves. */
function flattened(points: readonly Point[]) {
  const tree = flatteningTree(points, SPLIT_TOLERANCE);
  return {
    segments: tree.filter((node) => !node.split).length,
    whole: tree[0].flatness,
    half: tree.length > 1 ? tree[1].flatness : null,
  };
}

export const twoSegments: ExerciseSpec<RasterState> = {
  id: 'two-segments',
  title: 'Exactly two segments',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    // P₀ + P₂ even, so the chord's middle M is a whole pixel.
    const middle: Point = [r.int(10, 22), r.int(10, 14)];
    const half: Point = [r.int(6, 9), r.int(-3, 3)];
    const p0: Point = [middle[0] - half[0], middle[1] - half[1]];
    const p2: Point = [middle[0] + half[0], middle[1] + half[1]];
    const d = r.pick(DIRECTIONS);
    const far = r.int(2, 3);
    const at = (k: number): Point => [middle[0] + k * d[0], middle[1] + k * d[1]];
    const shaped = (p1: Point) =>
      sceneState(defaults, 'subdivide', [p0, p1, p2], { tolerance: SPLIT_TOLERANCE });
    const solution = shaped(at(1));
    const check = (s: RasterState): Verdict => {
      const [q0, q1, q2] = s.points;
      if (s.points.length !== 3 || distance(q0, p0) > 0 || distance(q2, p2) > 0)
        return {
          correct: false,
          message:
            'Move only P₁: P₀ and P₂ stay where they are, and the curve keeps its three points.',
        };
      const { segments, whole, half: halves } = flattened(s.points);
      const flat = `the whole curve’s flatness is ${words(whole)} px`;
      if (segments === 2)
        return {
          correct: true,
          message: `Correct: ${flat} > τ = ${SPLIT_TOLERANCE}, so it is split once, and each half’s ${words(halves ?? 0)} px ≤ τ.`,
        };
      return segments < 2
        ? {
            correct: false,
            message: `Not yet: ${flat} ≤ τ = ${SPLIT_TOLERANCE}, so it is one segment. Move P₁ further from the middle of P₀P₂ (now ${words(distance(q1, middle))} px away).`,
          }
        : {
            correct: false,
            message: `Not yet: ${segments} segments, as ${flat} and each half’s ${words(halves ?? 0)} px > τ = ${SPLIT_TOLERANCE}, so the halves are split again: bring P₁ closer to the middle of P₀P₂ (now ${words(distance(q1, middle))} px away).`,
          };
    };
    return {
      state: shaped(at(far)),
      prompt: `Keep P₀ ${pointWords(p0)} and P₂ ${pointWords(p2)}, and drag P₁ so that adaptive flattening to τ = ${SPLIT_TOLERANCE} px draws the quadratic with exactly two segments. The whole curve must be split at t = ½, and both halves must then be flat enough.`,
      task: { kind: 'construct', check, solution },
      // The test on the whole curve, the split, both halves flat: two segments.
      working: solution,
    };
  },
};
