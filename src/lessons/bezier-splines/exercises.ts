/**
 * Exercises of the Bézier splines lesson: a control point of the C¹
 * quadratic spline by reflections, a control point of the C² cubic spline by
 * solving its system by hand, and a joint made C² by moving two points.
 */
import {
  type ExerciseSpec,
  type Mistake,
  type Random,
  type Verdict,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { pointWords, sub, words } from '../../kit/format';
import {
  type Point,
  bezierJointReport,
  distance,
  quadraticSplineC1,
  solveCubicSplineC2System,
} from '../../math';
import { piecesOf } from './pieces';
import { inspector } from './script';
import { type BezierSplinesState, handTangents } from './state';

type State = BezierSplinesState;

/** "p₀ (0, 1), p₁ (2, 0) and p₂ (4, 2)": the points as the prompt lists them. */
function listed(points: readonly Point[]): string {
  const names = points.map((p, i) => `p${sub(i)} ${pointWords(p)}`);
  return `${names.slice(0, -1).join(', ')} and ${names[names.length - 1]}`;
}

/** The state of a part at step 0 through these points (with a hand-set tangent for each). */
const partState = (defaults: State, part: State['part'], points: Point[]): State => ({
  ...defaults,
  part,
  points,
  tangents: handTangents(points),
  step: 0,
});

/** Within this distance a guessed control point is right (about 3% of the figure). */
export const MIRROR_TOLERANCE = 0.25;

const mirrorControl: ExerciseSpec<State> = {
  id: 'mirror-control',
  title: 'Where is bₖ of the C¹ quadratic spline?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const points = Array.from({ length: 5 }, (_, i): Point => [2 * i, r.int(0, 2)]);
    const b0: Point = [r.pick([0.5, 1, 1.5]), r.int(0, 2)];
    const k = r.int(2, 3);
    // Step 0 shows the points alone: b₀ and the pieces come with the next steps.
    const state = { ...partState(defaults, 'quadratic', points), firstControl: [b0] };
    const b = quadraticSplineC1(points, b0).map((piece) => piece[1]);
    const answer = b[k];
    const [i, before] = [sub(k), sub(k - 1)];
    const slips: [Point, string][] = [
      [b[k - 1], `That is b${before}: reflect it in p${i} to get b${i}.`],
      [
        [2 * points[k - 1][0] - b[k - 1][0], 2 * points[k - 1][1] - b[k - 1][1]],
        `b${i} is b${before} reflected in p${i}, the joint of pieces ${k - 1} and ${k}, not in p${before}.`,
      ],
      [
        [(points[k][0] + points[k + 1][0]) / 2, (points[k][1] + points[k + 1][1]) / 2],
        `Only b₀ is chosen: every other bᵢ follows from it, bᵢ = 2pᵢ − bᵢ₋₁ (C¹ at pᵢ).`,
      ],
    ];
    const hint = (guess: Point) =>
      slips.find(([at]) => distance(guess, at) <= MIRROR_TOLERANCE)?.[1] ??
      `Reflect one point at a time: b₁ = 2p₁ − b₀, then b₂ = 2p₂ − b₁${k === 3 ? ', then b₃ = 2p₃ − b₂' : ''}.`;
    return {
      state,
      prompt: `The C¹ quadratic spline through ${listed(points)} starts with b₀ = ${pointWords(b0)}. Where is b${i}, the middle control point of the piece from p${i} to p${sub(k + 1)} (within ${MIRROR_TOLERANCE})?`,
      task: pointTask('main', answer, MIRROR_TOLERANCE, hint),
      // b₀, then one mirror image bᵢ = 2pᵢ − bᵢ₋₁ per step, with its numbers.
      working: state,
    };
  },
};

/** c₂ is asked to two decimals. */
export const SYSTEM_TOLERANCE = 0.01;

const c2System: ExerciseSpec<State> = {
  id: 'c2-system',
  title: 'Solve the C² system through three points',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    // p₂ − p₀ in multiples of 3, so c₂ = p₁ − (p₂ − p₀)/6 has at most one decimal (.5).
    const y0 = r.int(0, 3);
    const points: Point[] = [
      [0, y0],
      [r.int(2, 4), r.int(0, 5)],
      [3 * r.int(2, 3), y0 + 3 * r.pick([-1, 1])],
    ];
    const state = partState(defaults, 'system', points);
    const controls = solveCubicSplineC2System(points).controls;
    const answer = controls[2];
    const [c0, c3, c6] = points;
    // The slips: each is a wrong step of eliminating c₁, c₄, c₅ (see the hints).
    const sixth = [(c6[0] - c0[0]) / 6, (c6[1] - c0[1]) / 6];
    const along = (k: number): number[] => [c3[0] + k * sixth[0], c3[1] + k * sixth[1]];
    const mistakes: Mistake[] = [
      {
        values: along(1),
        hint: 'That is c₄, after the joint: c₂ comes before c₃ = p₁, so its sign is the other one (C¹: c₂ + c₄ = 2c₃).',
      },
      {
        values: along(-2),
        hint: 'Check the last elimination: with c₁ = (c₀ + c₂)/2, c₄ = 2c₃ − c₂ and c₅ = (c₄ + c₆)/2, the C² equation gives 6c₂ = c₀ + 6c₃ − c₆.',
      },
      {
        values: along(-3),
        hint: 'That uses the whole tangent (p₂ − p₀)/2 at p₁: the control point c₂ is a third of it before p₁.',
      },
      {
        values: [(c0[0] + answer[0]) / 2, (c0[1] + answer[1]) / 2],
        hint: 'That is c₁ = (c₀ + c₂)/2, from the natural end: the question asks for c₂.',
      },
    ];
    return {
      state,
      prompt: `The C² cubic spline through ${listed(points)} with natural ends has control points c₀ … c₆. Where is c₂, to 2 decimals?`,
      task: {
        kind: 'number',
        fields: ['x of c₂', 'y of c₂'],
        tolerance: SYSTEM_TOLERANCE,
        answer,
        check: (values) =>
          checkNumbers(
            values,
            answer,
            SYSTEM_TOLERANCE,
            'Write the 7 equations (3 points, C¹ and C² at c₃, natural ends), then eliminate c₁, c₄ and c₅.',
            mistakes,
          ),
      },
      // The unknowns, each kind of equation, the matrix, the solution (c₂ with its numbers).
      working: state,
    };
  },
};

/** P′ must agree to this (c₄ within about 0.17 of its place: 2% of the figure). */
export const VELOCITY_TOLERANCE = 0.5;
/** P″ must agree to this: 6|Δc₅ − 2Δc₄| ≤ 3. */
export const SECOND_TOLERANCE = 3;

/** Coordinates of the chain a student must leave alone: c₀ … c₃ and c₆. */
const FIXED = [0, 1, 2, 3, 6];

/** Away from `centre` along each axis by 1 or 2, so `target` lies between the centre and the result. */
const beyond = (r: Random, target: Point, centre: Point): Point =>
  target.map((v, d) => v + (v >= centre[d] ? 1 : -1) * r.int(1, 2));

/**
 * Two cubic pieces [c₀ c₁ c₂ c₃], [c₃ c₄ c₅ c₆] and where C² at c₃ puts c₄
 * and c₅: c₄ = 2c₃ − c₂ (C¹), c₅ = c₁ + 4(c₃ − c₂) (C²). c₃ − c₂ is (h, k) with
 * h = 1 or 2 and |k| ≤ 1, so c₅ stays near the chain.
 */
function jointData(r: Random) {
  const h = r.int(1, 2);
  const c: Point[] = [
    [0, r.int(0, 3)],
    [1, r.int(0, 3)],
    [2, r.int(1, 3)],
  ];
  c.push([2 + h, c[2][1] + r.int(-1, 1)]);
  const v = [c[3][0] - c[2][0], c[3][1] - c[2][1]];
  const c4: Point = [c[3][0] + v[0], c[3][1] + v[1]];
  const c5: Point = [c[1][0] + 4 * v[0], c[1][1] + 4 * v[1]];
  const c6: Point = [c5[0] + r.int(1, 2), r.int(0, 3)];
  return { fixed: c, c4, c5, c6 };
}

const c2Joint: ExerciseSpec<State> = {
  id: 'c2-joint',
  title: 'Make a joint C²',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const { fixed, c4, c5, c6 } = jointData(r);
    const others = [...fixed, c6];
    const centre: Point = [0, 1].map((d) => others.reduce((sum, q) => sum + q[d], 0) / 5);
    // The posed c₄ and c₅ lie beyond their places, so the figure fitted to them shows both places.
    const chain = (q4: Point, q5: Point): State => {
      const state = { ...defaults, part: 'inspector' as const, handBuilt: [...fixed, q4, q5, c6] };
      // The verdict, the velocities and the curvature at the joint are shown from this step on.
      return { ...state, step: inspector.stepOf(state, 'curvature') };
    };
    const solution = chain(c4, c5);
    const check = (s: State): Verdict => {
      const q = s.handBuilt;
      const moved = q.length !== 7 || FIXED.some((j) => distance(q[j], solution.handBuilt[j]) > 0);
      if (s.part !== 'inspector' || moved)
        return {
          correct: false,
          message: 'Move only c₄ and c₅: the other points stay where they are.',
        };
      const [left, right] = piecesOf(q);
      const joint = bezierJointReport(left, right);
      const velocity = distance(joint.leftVelocity, joint.rightVelocity);
      const second = distance(joint.leftSecond, joint.rightSecond);
      const numbers = `At c₃, P′ is ${pointWords(joint.leftVelocity)} on the left and ${pointWords(joint.rightVelocity)} on the right; P″ is ${pointWords(joint.leftSecond)} and ${pointWords(joint.rightSecond)}.`;
      if (velocity > VELOCITY_TOLERANCE)
        return {
          correct: false,
          message: `Not yet. ${numbers} First C¹: P′ = 3(c₄ − c₃) must equal 3(c₃ − c₂), so c₄ = 2c₃ − c₂.`,
        };
      if (second > SECOND_TOLERANCE)
        return {
          correct: false,
          message: `Not yet: C¹ holds, but P″ differs by ${words(second)}. ${numbers} C²: 6(c₃ − 2c₄ + c₅) must equal 6(c₁ − 2c₂ + c₃), so c₅ = c₁ − 2c₂ + 2c₄.`,
        };
      return {
        correct: true,
        message: `Correct: C² at c₃, P′ agree to ${words(velocity)} and P″ to ${words(second)}.`,
      };
    };
    return {
      state: chain(beyond(r, c4, centre), beyond(r, c5, centre)),
      prompt: `Keep c₁ ${pointWords(fixed[1])}, c₂ ${pointWords(fixed[2])}, c₃ ${pointWords(fixed[3])} and the other points where they are, and drag c₄ and c₅ until the joint at c₃ is C². P′ must agree there within ${VELOCITY_TOLERANCE} and P″ within ${SECOND_TOLERANCE}.`,
      task: { kind: 'construct', check, solution },
      // The C² chain from the joints up: its pieces, the verdict C², tangents, curvature, comb.
      working: { ...solution, step: 0 },
    };
  },
};

/** The lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<State>[] = [mirrorControl, c2System, c2Joint];
