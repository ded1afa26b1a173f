import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/lagrange';
import { defaultsOf } from '../../app/urlState';
import { degenerate } from '../../kit/degenerate';
import type { ExerciseSpec, Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import type { Bounds } from '../../render/projection';
import { GUESS_TOLERANCE, STEER_TOLERANCE, exercises } from './exercises';
import lesson from './lesson';
import type { LagrangeModel } from './model';
import { type LagrangeState, schema } from './state';

const defaults = defaultsOf(schema);
const exercise = (id: string) => exercises.find((e) => e.id === id) as ExerciseSpec<LagrangeState>;
const pose = (id: string, seed: number) => exercise(id).pose(seed, defaults);
const derive = (s: LagrangeState) => lesson.derive(s) as LagrangeModel;
const lastStep = (s: LagrangeState) => lesson.steps!.count(s);
/** The frame the app fits the curve's figure to. */
const frame = (s: LagrangeState): Bounds =>
  lesson.figures.find((f) => f.id === 'curve')!.bounds(derive(s));
const inside = (p: Point, b: Bounds) =>
  p[0] >= b.minX && p[0] <= b.maxX && p[1] >= b.minY && p[1] <= b.maxY;
const closeTo = (actual: readonly number[], expected: readonly number[]) =>
  expected.forEach((v, d) => expect(actual[d]).toBeCloseTo(v, 9));

function task<K extends 'point' | 'number' | 'construct'>(posed: Posed<LagrangeState>, kind: K) {
  expect(posed.task.kind).toBe(kind);
  return posed.task as Extract<Posed<LagrangeState>['task'], { kind: K }>;
}

// The nodes are 0, 0.25, 0.5, 0.75, 1, so the weights at a tenth have four decimals:
//        L0       L1       L2       L3       L4
// 0.4  −0.0336   0.3584   0.8064  −0.1536   0.0224
// 0.7   0.0144  −0.0896   0.3024   0.8064  −0.0336
// e.g. L3(0.4) = (0.4)(0.15)(−0.1)(−0.6) / ((0.75)(0.5)(0.25)(−0.25)) = 0.0036 / −0.0234375.

describe('the Lagrange lesson’s exercises', () => {
  it('are the lesson’s, and pass the kit’s checks, the point to guess inside the figure’s frame', () => {
    expect(lesson.exercises).toBe(exercises);
    checkExercises(exercises, defaults, {
      inFigure: (state, answer) => answer.every(Number.isFinite) && inside(answer, frame(state)),
    });
  });

  it('where: P(0.7) through five points, seed 1, worked by hand', () => {
    const posed = pose('where', 1);
    expect(posed.prompt).toBe(
      'The polynomial passes P₀ … P₄ at t = 0, 0.25, 0.5, 0.75, 1. Where is P(0.7)?',
    );
    expect(posed.state.points).toEqual([
      [0, 2],
      [2, 3],
      [3, 3],
      [4, 1],
      [6, 2],
    ]);
    // x = 0.0144·0 − 0.0896·2 + 0.3024·3 + 0.8064·4 − 0.0336·6 = −0.1792 + 0.9072 + 3.2256 − 0.2016,
    // y = 0.0144·2 − 0.0896·3 + 0.3024·3 + 0.8064·1 − 0.0336·2 = 0.0288 − 0.2688 + 0.9072 + 0.8064 − 0.0672.
    const point = task(posed, 'point');
    closeTo(point.answer, [3.752, 1.4064]);
    expect(point.figure).toBe('curve');
    expect(point.check([3.8, 1.3]).correct).toBe(true);
    const wrong = point.check([3.5, 3]);
    expect(wrong.correct).toBe(false);
    expect(wrong.message).toContain('between t₂ = 0.5 and t₃ = 0.75');
    // Step 0 draws the points alone, and the panel's P(t) at t = 0 is P₀.
    expect(derive(posed.state).shown.has('curve')).toBe(false);
    expect(derive(posed.state).at).toEqual([0, 2]);
    // The working ends on the polynomial with P(0.7) drawn and written.
    const end = derive(posed.working);
    expect(end.shown.has('curve')).toBe(true);
    closeTo(end.at, [3.752, 1.4064]);
  });

  it('weight: L₃(0.4), seed 1, with the hint for each slip', () => {
    const posed = pose('weight', 1);
    expect(posed.prompt).toBe(
      'The five points have tₖ = 0, 0.25, 0.5, 0.75, 1. Compute L₃(0.4) to 3 decimals (within 0.001).',
    );
    const number = task(posed, 'number');
    expect(number.fields).toEqual(['L₃(0.4)']);
    closeTo(number.answer, [-0.1536]);
    expect(number.check([-0.154]).correct).toBe(true);
    expect(number.check([-0.151]).correct).toBe(false);
    const hint = (v: number) => number.check([v]).message;
    // Upside down: −0.0234375 / 0.0036 = −6.5104.
    expect(hint(-6.5104)).toContain('upside down');
    // The neighbours: L2(0.4) = 0.8064, L4(0.4) = 0.0224.
    expect(hint(0.8064)).toContain('That is L₂(0.4)');
    expect(hint(0.0224)).toContain('That is L₄(0.4)');
    expect(hint(0.1536)).toContain('Check the sign');
    // Nodes 0 … 4: (0.4/3)(−0.6/2)(−1.6/1)(−3.6/−1) = 0.2304.
    expect(hint(0.2304)).toContain('not 0, 1, 2, 3, 4');
    expect(hint(0.5)).toContain('Work through the product again');
    // Step 0 plots no Lₖ, and at t = 0 the panel's weights are 1 and 0s.
    expect(derive(posed.state).shown.count('basis')).toBe(0);
    expect(derive(posed.state).weights.map((w) => w + 0)).toEqual([1, 0, 0, 0, 0]);
    expect(derive({ ...posed.working, step: 4 }).weights[3]).toBeCloseTo(-0.1536, 12);
  });

  it('steer: P₃ dragged so P(0.7) lands on its target, seed 1', () => {
    const posed = pose('steer', 1);
    // The same points as 'where' seed 1, but P3 opens at (4, −1), two below (4, 1):
    // P(0.7) = (3.752, 1.4064) + L3(0.7)·(0, −2) = (3.752, 1.4064 − 1.6128) = (3.752, −0.2064).
    expect(posed.prompt).toBe(
      'Drag P₃ alone until the dot P(0.7) sits at (3.75, 1.41), within 0.1.',
    );
    expect(posed.state.points[3]).toEqual([4, -1]);
    const construct = task(posed, 'construct');
    const before = construct.check(posed.state);
    expect(before.correct).toBe(false);
    expect(before.message).toContain('P(0.7) is at (3.752, −0.206), 1.616 from (3.75, 1.41)');
    expect(before.message).toContain('L₃(0.7) = 0.806');
    expect(before.message).toContain('the same way');
    expect(construct.solution.points[3]).toEqual([4, 1]);
    expect(construct.check(construct.solution).correct).toBe(true);
    const withP3 = (p3: Point) => ({
      ...posed.state,
      points: posed.state.points.map((p, k) => (k === 3 ? p3 : p)),
    });
    // P(0.7) moves 0.8064 times P3's move: 0.1 up is 0.081 (plus the 0.004 of rounding), 0.15 up is not.
    expect(construct.check(withP3([4, 1.1])).correct).toBe(true);
    expect(construct.check(withP3([4, 1.15])).correct).toBe(false);
    const p1Moved = construct.solution.points.map((p, k) => (k === 1 ? [2, 2] : p));
    expect(construct.check({ ...construct.solution, points: p1Moved }).message).toBe(
      'Move only P₃: put P₁ back at (2, 3).',
    );
    expect(construct.check({ ...construct.solution, t: 0.5 }).message).toBe(
      'Put t back at 0.7: the dot is P(0.7).',
    );
    expect(construct.check({ ...construct.solution, spacing: 'chord' }).correct).toBe(false);
    expect(
      construct.check({ ...construct.solution, points: posed.state.points.slice(1) }).message,
    ).toContain('Keep the five points');
    expect(derive(posed.state).shown.has('curve')).toBe(true);
  });

  it('steer: a negative weight says the point pulls P(t) the opposite way', () => {
    const posed = pose('steer', 7);
    // Seed 7 moves P2 for P(0.2), where L2(0.2) = −0.2816.
    expect(posed.prompt).toContain('Drag P₂ alone until the dot P(0.2)');
    const message = task(posed, 'construct').check(posed.state).message;
    expect(message).toContain('L₂(0.2) = −0.282');
    expect(message).toContain('the opposite way');
  });

  it('agrees with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });

  it('every seed: five points in order, never on one line, workings walked to their end', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        for (const e of exercises) {
          const posed = e.pose(seed, defaults);
          expect(posed.working.step).toBe(lastStep(posed.working));
          for (const s of [posed.state, posed.working]) {
            expect(s.points).toHaveLength(5);
            expect(derive(s).note).toBeNull();
          }
          expect(degenerate(posed.state.points).repeats).toEqual([]);
        }
      }),
    );
  });

  it('every seed: where is hidden at step 0, with a strict tolerance', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('where', seed);
        expect(task(posed, 'point').tolerance).toBe(GUESS_TOLERANCE);
        expect(derive(posed.state).shown.has('curve')).toBe(false);
      }),
    );
  });

  it('every seed: weight refuses an answer 2 tolerances off', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const number = task(pose('weight', seed), 'number');
        expect(number.check([number.answer[0] + 2 * number.tolerance]).correct).toBe(false);
      }),
    );
  });

  it('every seed: steer’s target and solution are on the figure, its tolerance a finger’s reach', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('steer', seed);
        const { solution } = task(posed, 'construct');
        const view = frame(posed.state);
        const target = posed.prompt.match(/sits at \((−?[\d.]+), (−?[\d.]+)\)/)!;
        const [x, y] = [target[1], target[2]].map((v) => Number(v.replace('−', '-')));
        expect(inside([x, y], view)).toBe(true);
        solution.points.forEach((p) => expect(inside(p, view)).toBe(true));
        // A finger's reach: about 1–2% of the figure's span.
        const share = STEER_TOLERANCE / Math.max(view.maxX - view.minX, view.maxY - view.minY);
        expect(share).toBeGreaterThan(0.01);
        expect(share).toBeLessThan(0.025);
      }),
    );
  });
});
