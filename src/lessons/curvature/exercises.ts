import {
  type ExerciseSpec,
  type Random,
  type Verdict,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { pointWords, sub, words } from '../../kit/format';
import {
  type Point,
  bezierChainSegments,
  bezierCurvature,
  bezierJointReport,
  bezierTangent,
  distance,
  norm,
  osculatingCircle,
} from '../../math';
import { PART_SCRIPTS } from './scripts';
import type { CurvatureState } from './state';

// The lesson's exercises: the centre of the osculating circle, κ of a cubic
// by the formula, and two cubic pieces made curvature-continuous at their join.

/** The plane part with one curve of these points (Bézier, or cubic pieces), at step 0. */
function planeState(
  defaults: CurvatureState,
  source: 'bezier' | 'chain',
  points: Point[],
  t: number,
): CurvatureState {
  return { ...defaults, part: 'plane', source, points, gradients: [], t, step: 0 };
}

/**
 * An arch of whole coordinates: P0 and P3 on its base w apart, P1 and P2 at
 * heights w − 1 or w over (or near) them, mirrored upside down half the time
 * and moved by whole steps. At t = 0.4 … 0.6 its osculating circle has a
 * radius under 0.8 of its size and a centre inside its box (tested).
 */
function arch(r: Random): Point[] {
  const w = r.int(3, 5);
  const shape: Point[] = [
    [0, 0],
    [r.int(0, 1), w - r.int(0, 1)],
    [w - r.int(0, 1), w - r.int(0, 1)],
    [w, 0],
  ];
  const flip = r.int(0, 1) === 0 ? 1 : -1;
  const [dx, dy] = [r.int(0, 2), r.int(0, 2)];
  return shape.map(([x, y]) => [x + dx, flip * y + dy]);
}

const pointName = (i: number) => `P${sub(i)}`;
const pointsText = (points: readonly Point[]) =>
  points.map((p, i) => `${pointName(i)} = ${pointWords(p)}`).join(', ');

/** Where is the centre of the osculating circle at P(t)? */
const circleCentre: ExerciseSpec<CurvatureState> = {
  id: 'circle-centre',
  title: 'Where is the centre of curvature?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const points = arch(r);
    const t = r.pick([0.4, 0.5, 0.6]);
    const answer = osculatingCircle(points, t).centre;
    const tolerance = 0.2;
    // The cursor at the end whose circle is farther from the answer: the panel's N and R are its.
    const [start, end] = [0, 1].map((u) => distance(osculatingCircle(points, u).centre, answer));
    return {
      state: planeState(defaults, 'bezier', points, start >= end ? 0 : 1),
      prompt: `The osculating circle at P(${t}) touches the curve with radius 1/|κ|. Where is its centre (within ${tolerance})?`,
      task: pointTask(
        'curve',
        answer,
        tolerance,
        `The centre is P(t) + N/|κ|: from P(${t}) along the normal N, on the inside of the bend, a distance R = 1/|κ| (the steps “normal” and “curvature”).`,
      ),
      working: planeState(defaults, 'bezier', points, t),
    };
  },
};

/** κ of a cubic at t = 0, ½ or 1 by κ = (x′y″ − y′x″)/|P′|³. */
const curvatureValue: ExerciseSpec<CurvatureState> = {
  id: 'curvature-value',
  title: 'Compute the curvature κ',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const points = arch(r);
    const t = r.pick([0, 0.5, 1]);
    const kappa = bezierCurvature(points, t);
    const speed = norm(bezierTangent(points, t));
    const tolerance = 0.001;
    const slips = [
      {
        values: [1.5 * kappa],
        hint: `The velocity step: a cubic's P′ carries a factor 3 (P′(0) = 3(P₁ − P₀)) and its P″ a factor 6; without them κ comes out 3/2 times too large.`,
      },
      {
        values: [kappa * speed],
        hint: `The curvature step divides x′y″ − y′x″ by |P′|³, the cube of the speed, not its square.`,
      },
      {
        values: [-kappa],
        hint: `The sign: κ = (x′y″ − y′x″)/|P′|³ is positive where the curve turns left (anticlockwise), negative where it turns right.`,
      },
      {
        values: [1 / Math.abs(kappa)],
        hint: `That is the radius R = 1/|κ| of the osculating circle; κ is its reciprocal, with the sign of the turn.`,
      },
      ...(t === 0.5
        ? []
        : [
            {
              values: [bezierCurvature(points, 1 - t)],
              hint: `t and 1 − t are swapped: that is κ at the other end, t = ${1 - t}. At t = 0 the curve leaves P₀ towards P₁.`,
            },
          ]),
    ];
    return {
      // Step 0 shows only the curve, and the cursor (the panel's κ) is at t = 0.3, not at t.
      state: planeState(defaults, 'bezier', points, 0.3),
      prompt: `For the cubic Bézier curve with ${pointsText(points)}, what is the curvature κ at t = ${t}? Give it to 3 decimals (within ${tolerance}).`,
      task: {
        kind: 'number',
        fields: [`κ(${t})`],
        tolerance,
        answer: [kappa],
        check: (values) =>
          checkNumbers(
            values,
            [kappa],
            tolerance,
            `Work the steps in order: the velocity P′(${t}), then P″(${t}), then κ = (x′y″ − y′x″)/|P′|³.`,
            slips,
          ),
      },
      working: planeState(defaults, 'bezier', points, t),
    };
  },
};

/** The largest angle, in degrees, between the tangents at the join that still counts as one tangent. */
const ANGLE = 2;

/** Two cubic pieces that meet with one tangent at P3: move P5 until κ is the same on both sides. */
const smoothJoin: ExerciseSpec<CurvatureState> = {
  id: 'smooth-join',
  title: 'Make κ continuous at a join',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    // P2, P3, P4 on the line y = 3, 2 apart (a C¹ join); s says on which side the pieces bend.
    const s = r.int(0, 1) === 0 ? 1 : -1;
    const y = (height: number) => 3 - s * height;
    const [wx, wy] = [r.int(1, 2), r.int(1, 2)];
    const vx = r.int(1, 2);
    const vy = r.pick([0, 1, 2, 3].filter((h) => h !== wy));
    const points: Point[] = [
      [0, y(r.int(1, 3))],
      [4 - wx, y(wy)],
      [4, 3],
      [6, 3],
      [8, 3],
      [8 + vx, y(vy)],
      [12, y(r.int(0, 3))],
    ];
    const tolerance = 0.03;
    const base = planeState(defaults, 'chain', points, 0.5);
    // κ after the join is −s·vy/6 and before it −s·wy/6: P5 as far from the line as P1.
    const solution = { ...base, points: points.map((p, i) => (i === 5 ? [p[0], y(wy)] : p)) };
    return {
      // The whole construction with the comb and the κ plot, where the jump shows.
      state: { ...base, step: PART_SCRIPTS.plane.lastStep(base) },
      prompt: `The two cubic pieces meet at P₃ with one tangent, but κ jumps there. Move P₅ so that κ is the same on both sides of the join (within ${tolerance}).`,
      task: { kind: 'construct', check: (state) => joinVerdict(state, tolerance), solution },
      working: solution,
    };
  },
};

/** How the two pieces of P0 … P6 meet at P3: one tangent, and κ on either side. */
function joinVerdict(state: CurvatureState, tolerance: number): Verdict {
  const [left, right] = bezierChainSegments(state.points.slice(0, 7), 3);
  const joint = bezierJointReport(left, right);
  if (!Number.isFinite(joint.leftCurvature) || !Number.isFinite(joint.rightCurvature))
    return {
      correct: false,
      message: `Not yet: a control point sits on P₃, so the speed there is 0 and κ is undefined. Move P₂ and P₄ off P₃ again.`,
    };
  if (!(joint.angle <= ANGLE))
    return {
      correct: false,
      message: `Not yet: the tangents at P₃ differ by ${words(joint.angle)}°, a corner. Keep P₂, P₃ and P₄ on one line, then match κ with P₅.`,
    };
  const [before, after] = [joint.leftCurvature, joint.rightCurvature];
  const gap = Math.abs(after - before);
  return gap <= tolerance
    ? {
        correct: true,
        message: `Correct: κ is ${words(before)} just before P₃ and ${words(after)} just after (they differ by ${words(gap)}): the curvature is continuous there.`,
      }
    : {
        correct: false,
        message: `Not yet: κ is ${words(before)} just before P₃ and ${words(after)} just after, ${words(gap)} apart. P₅ must be as far from the tangent line through P₂, P₃, P₄ as P₁ is, on the same side.`,
      };
}

/** The lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<CurvatureState>[] = [
  circleCentre,
  curvatureValue,
  smoothJoin,
];
