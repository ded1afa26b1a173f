import {
  type ExerciseSpec,
  type Random,
  type Verdict,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { degenerate } from '../../kit/degenerate';
import { pointWords, words } from '../../kit/format';
import {
  distance,
  hermiteCoefficients,
  hermitePoint,
  hermiteToBezier,
  type Point,
  scale,
} from '../../math';
import { hermiteLectureCoefficients } from '../../math/hermite';
import { spline } from './model';
import { bezierScript, construction } from './script';
import type { HermiteState } from './state';

// The lesson's practice: where P(μ) is on a patch from its ends and gradients,
// a₂ and a₃ of a patch by equation 7, and the gradients that make a patch a
// given Bézier curve (B₁ the tip of D₀’s arrow, B₂ D₁’s tip mirrored through P₁).

/** How far a guessed point may be from P(μ): about 3% of the figure (some 7 units across). */
export const GUESS_TOLERANCE = 0.2;
/** How close B₁ and B₂ must come: about 1.5% of the figure (some 10 units across), a finger's reach. */
export const BEZIER_TOLERANCE = 0.15;

/** Printed digits only: 1.8750000000000002 is shown, and checked, as 1.875. */
const clean = (p: readonly number[]) => p.map((v) => Number(v.toPrecision(12)));

/** A gradient in thirds-friendly numbers: 3 or 6 across, −6 … 6 up, so its arrow D/3 ends on the grid. */
const gradient = (r: Random): Point => [3 * r.int(1, 2), 3 * r.int(-2, 2)];

/** The exercise's figure: these points and hand-set gradients, patch `patch`, at step `step`. */
const setUp = (
  defaults: HermiteState,
  points: Point[],
  handGradients: Point[],
  changes: Partial<HermiteState>,
): HermiteState => ({
  ...defaults,
  points,
  handGradients,
  mode: 'hand',
  patch: 0,
  bezier: false,
  ...changes,
});
const lastStep = (s: HermiteState) => construction.lastStep(s);

const where: ExerciseSpec<HermiteState> = {
  id: 'where',
  title: 'Where is P(μ)?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const points: Point[] = [
      [0, r.int(0, 2)],
      [r.int(4, 6), r.int(0, 2)],
    ];
    const gradients = [gradient(r), gradient(r)];
    const mu = r.pick([0.25, 0.5, 0.75]);
    const [p0, p1] = points;
    const [d0, d1] = gradients;
    const answer = clean(hermitePoint(p0, d0, p1, d1, mu));
    // Step 1 draws the points and the gradients' arrows, not the patch; at μ = 0 the panel's P(μ) is P₀.
    const state = setUp(defaults, points, gradients, { mu: 0, step: 1 });
    const hint = `Weight the four data with the Hermite basis at μ = ${mu}: P(μ) = H₀P₀ + H₁P₁ + H₂D₀ + H₃D₁, with the gradients D themselves (each arrow is a third of its D).`;
    return {
      state,
      prompt: `The patch leaves P₀ = ${pointWords(p0)} with gradient D₀ = ${pointWords(d0)} and arrives at P₁ = ${pointWords(p1)} with D₁ = ${pointWords(d1)}. Where is P(${mu})?`,
      task: pointTask('patches', answer, GUESS_TOLERANCE, hint),
      // The patch solved, H₀ … H₃ read off the inverse, and P(μ) from them.
      working: { ...state, mu, step: lastStep(state) },
    };
  },
};

const coefficients: ExerciseSpec<HermiteState> = {
  id: 'coefficients',
  title: 'a₂ and a₃ of a patch by equation 7',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    let points: Point[];
    do
      points = [
        [0, r.int(0, 2)],
        [r.int(2, 3), r.int(1, 3)],
        [r.int(5, 6), r.int(0, 2)],
      ];
    while (degenerate(points).collinear);
    const gradients: Point[] = points.map(() => [r.int(1, 3), r.int(-2, 2)]);
    const [p1, p2] = points.slice(1);
    const [d1, d2] = gradients.slice(1);
    const a23 = (a: readonly Point[]) => clean([...a[2], ...a[3]]);
    const answer = a23(hermiteCoefficients(p1, d1, p2, d2));
    const mistakes = [
      {
        values: a23(hermiteLectureCoefficients(p1, p2, d1, d2)),
        hint: 'Equation 7 takes the data in the lecture’s order P₁, D₁, P₂, D₂; you used P₁, P₂, D₁, D₂, the continuation notes’ order.',
      },
      {
        values: [...answer.slice(2), ...answer.slice(0, 2)],
        hint: 'You swapped a₂ and a₃: a₂ is the row (−3, −2, 3, −1) of the inverse, a₃ the row (2, 1, −2, 1).',
      },
      {
        values: a23(hermiteCoefficients(points[0], gradients[0], p1, d1)),
        hint: 'That is patch 1, from P₀ to P₁: patch 2 runs from P₁ to P₂, with D₁ and D₂.',
      },
      {
        values: a23(hermiteCoefficients(p1, scale(d1, 1 / 3), p2, scale(d2, 1 / 3))),
        hint: 'Those are the arrows, a third of each gradient: use D₁ and D₂ themselves.',
      },
    ];
    const hint =
      'Multiply the rows (−3, −2, 3, −1) and (2, 1, −2, 1) of equation 7’s inverse by P₁, D₁, P₂, D₂, one coordinate at a time.';
    // The panel shows patch 1's coefficients, not patch 2's; step 1 draws no patch.
    const state = setUp(defaults, points, gradients, { step: 1 });
    return {
      state,
      prompt: `Patch 2 runs from P₁ = ${pointWords(p1)} to P₂ = ${pointWords(p2)}, with gradients D₁ = ${pointWords(d1)} and D₂ = ${pointWords(d2)}. Compute a₂ and a₃ of its P(μ) = a₃μ³ + a₂μ² + a₁μ + a₀, each to 2 decimals (within 0.01).`,
      task: {
        kind: 'number',
        fields: ['a₂ x', 'a₂ y', 'a₃ x', 'a₃ y'],
        tolerance: 0.01,
        answer,
        check: (values) => checkNumbers(values, answer, 0.01, hint, mistakes),
      },
      // Conditions and matrix of patch 2, then each patch solved in turn: patch 2's a₀ … a₃.
      working: { ...state, patch: 1, step: lastStep(state) },
    };
  },
};

/**
 * The patch as a target Bézier curve: B₀ = P₀ and B₃ = P₁ on the grid, B₁
 * and B₂ a unit or two in from them; and gradients that open it elsewhere,
 * with both target tips (B₁, and B₂ mirrored through P₁) on the figure.
 */
function bezierTarget(r: Random, defaults: HermiteState) {
  for (;;) {
    const b0: Point = [0, r.int(0, 2)];
    const b3: Point = [r.int(5, 6), r.int(0, 2)];
    const b1: Point = [r.int(1, 2), r.int(0, 4)];
    const b2: Point = [b3[0] - r.int(1, 2), r.int(0, 4)];
    // The tips that make it: B₁, and P₁ + (P₁ − B₂).
    const tips = [b1, [2 * b3[0] - b2[0], 2 * b3[1] - b2[1]]];
    // Each tip opens up to a unit across and one or two up or down from its place.
    const ends = [b0, b3];
    const gradients = tips.map((tip, k): Point => {
      const [dx, dy] = [r.pick([-1, 0, 1]), r.pick([-2, -1, 1, 2])];
      return [3 * (tip[0] + dx - ends[k][0]), 3 * (tip[1] + dy - ends[k][1])];
    });
    const base = setUp(defaults, ends, gradients, { mu: 0.3, step: 0 });
    const state = { ...base, step: lastStep(base) };
    const { minX, maxX, minY, maxY } = spline(state).bounds;
    const shown = (q: readonly number[]) =>
      q[0] >= minX && q[0] <= maxX && q[1] >= minY && q[1] <= maxY;
    // No tip on a point: a zero gradient's handle would sit under its point's.
    if (tips.every(shown) && gradients.every((d) => d[0] !== 0 || d[1] !== 0))
      return { state, b1, b2, tips };
  }
}

const bezier: ExerciseSpec<HermiteState> = {
  id: 'bezier',
  title: 'Make the patch a given Bézier curve',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const { state, b1, b2, tips } = bezierTarget(r, defaults);
    const [p0, p1] = state.points;
    const check = (s: HermiteState): Verdict => {
      if (s.points.length !== 2)
        return { correct: false, message: 'Keep one patch: remove the points you added.' };
      const moved = s.points.findIndex((p, k) => distance(p, state.points[k]) > 1e-9);
      if (moved !== -1)
        return {
          correct: false,
          message: `B${moved === 0 ? '₀' : '₃'} is the patch’s end P${moved === 0 ? '₀' : '₁'}: put it back at ${pointWords(state.points[moved])}.`,
        };
      const [d0, d1] = spline(s).gradients;
      const [, c1, c2] = hermiteToBezier(p0, d0, p1, d1);
      const off = [distance(c1, b1), distance(c2, b2)];
      if (off.every((v) => v <= BEZIER_TOLERANCE))
        return {
          correct: true,
          message: `Correct: B₁ is ${words(off[0])} and B₂ ${words(off[1])} from their places, so D₀ = ${pointWords(d0)} and D₁ = ${pointWords(d1)} make the patch this Bézier curve.`,
        };
      const notes = [
        off[0] > BEZIER_TOLERANCE
          ? `B₁ = P₀ + D₀/3, the tip of D₀’s arrow, is at ${pointWords(c1)}, ${words(off[0])} from ${pointWords(b1)}.`
          : '',
        off[1] > BEZIER_TOLERANCE
          ? `B₂ = P₁ − D₁/3 is at ${pointWords(c2)}, ${words(off[1])} from ${pointWords(b2)}: it is D₁’s tip mirrored through P₁.`
          : '',
      ];
      return { correct: false, message: notes.filter(Boolean).join(' ') };
    };
    const solution = {
      ...state,
      handGradients: tips.map((tip, k) =>
        scale([tip[0] - state.points[k][0], tip[1] - state.points[k][1]], 3),
      ),
    };
    return {
      state,
      prompt: `Drag the gradients’ tips until this patch is the cubic Bézier curve with B₁ = ${pointWords(b1)} and B₂ = ${pointWords(b2)}, each within ${BEZIER_TOLERANCE}.`,
      task: { kind: 'construct', check, solution },
      // The Bézier view of the solution: B₀ … B₃, its ends and gradients, one cubic.
      working: { ...solution, bezier: true, step: bezierScript.lastStep(solution) },
    };
  },
};

/** The Hermite lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<HermiteState>[] = [where, coefficients, bezier];
