import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/quadratic';
import { defaultsOf } from '../../app/urlState';
import type { ExerciseSpec, Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import { degenerate } from '../../kit/degenerate';
import type { Point } from '../../math';
import type { Bounds } from '../../render/projection';
import { GUESS_TOLERANCE, STEER_TOLERANCE, exercises } from './exercises';
import lesson from './lesson';
import type { QuadraticModel } from './model';
import { LAST_STEP, type QuadraticState, schema } from './state';

const defaults = defaultsOf(schema);
const exercise = (id: string) => exercises.find((e) => e.id === id) as ExerciseSpec<QuadraticState>;
const pose = (id: string, seed: number) => exercise(id).pose(seed, defaults);
const derive = (s: QuadraticState) => lesson.derive(s) as QuadraticModel;
/** The frame the app fits the figure to. */
const frame = (s: QuadraticState): Bounds => lesson.figures[0].bounds(derive(s));
/** Within the frame, to rounding (the frame is fitted to samples of the same curve). */
const inside = (p: Point, b: Bounds, e = 1e-9) =>
  p[0] >= b.minX - e && p[0] <= b.maxX + e && p[1] >= b.minY - e && p[1] <= b.maxY + e;
const closeTo = (actual: readonly number[], expected: readonly number[]) =>
  expected.forEach((v, d) => expect(actual[d]).toBeCloseTo(v, 9));

function task<K extends 'point' | 'number' | 'construct'>(posed: Posed<QuadraticState>, kind: K) {
  expect(posed.task.kind).toBe(kind);
  return posed.task as Extract<Posed<QuadraticState>['task'], { kind: K }>;
}

describe('the quadratic lesson’s exercises', () => {
  it('are the lesson’s, and pass the kit’s checks, the point to guess inside the figure’s frame', () => {
    expect(lesson.exercises).toBe(exercises);
    checkExercises(exercises, defaults, {
      inFigure: (state, answer) => answer.every(Number.isFinite) && inside(answer, frame(state)),
    });
  });

  it('where: P(0.7) with μ₁ = 0.6, seed 1, worked by hand', () => {
    const posed = pose('where', 1);
    // P0 = (0, 1), P1 = (1, 4), P2 = (6, 2), μ1 = 0.6, μ = 0.7. Weights of the Lagrange form:
    // w0 = (μ − μ1)(μ − 1)/μ1 = (0.1)(−0.3)/0.6 = −0.05,
    // w1 = μ(μ − 1)/(μ1(μ1 − 1)) = (−0.21)/(−0.24) = 0.875, w2 = μ(μ − μ1)/(1 − μ1) = 0.07/0.4 = 0.175.
    // x = 0.875·1 + 0.175·6 = 1.925, y = −0.05·1 + 0.875·4 + 0.175·2 = 3.8.
    expect(posed.prompt).toBe(
      'P(μ) passes P₀ = (0, 1) at μ = 0, P₁ = (1, 4) at μ₁ = 0.6 and P₂ = (6, 2) at μ = 1. Where is P(0.7)?',
    );
    const point = task(posed, 'point');
    closeTo(point.answer, [1.925, 3.8]);
    expect(point.figure).toBe('quadratic');
    expect(point.check([1.95, 3.75]).correct).toBe(true);
    const wrong = point.check([1, 4]);
    expect(wrong.correct).toBe(false);
    expect(wrong.message).toContain('μ = 0.7 comes after μ₁ = 0.6');
    expect(wrong.message).toContain('between P₁ and P₂');
    // Step 0 draws the points alone; the working's dots of equal μ include μ = 0.7.
    expect(posed.state.step).toBe(0);
    expect(derive(posed.state).parametric.current).toBeNull();
    const dots = derive(posed.working).parametric.current!.ticks;
    closeTo(dots[7], [1.925, 3.8]);
  });

  it('compute: P(0.7) from equations 2 and 3, seed 1, with the hint for each slip', () => {
    const posed = pose('compute', 1);
    // P0 = (0, 1), P1 = (1, 4), P2 = (6, 2), μ1 = 0.5: a0 = P0;
    // a2 = (P1 − P0 − ½(P2 − P0)) / (−¼) = 2P0 − 4P1 + 2P2 = (8, −10); a1 = P2 − P0 − a2 = (−2, 11).
    // P(0.7) = a0 + 0.7a1 + 0.49a2 = (−1.4 + 3.92, 1 + 7.7 − 4.9) = (2.52, 3.8).
    expect(posed.prompt).toContain('P₁ = (1, 4) at μ₁ = 0.5');
    expect(posed.prompt).toContain('Compute P(0.7) to 2 decimals (within 0.01).');
    const number = task(posed, 'number');
    closeTo(number.answer, [2.52, 3.8]);
    expect(number.tolerance).toBe(0.01);
    expect(number.check([2.52, 3.8])).toEqual({ correct: true, message: 'Correct.' });
    expect(number.check([2.525, 3.795]).correct).toBe(true);
    const hint = (values: number[]) => number.check(values).message;
    // a2 = (−8, 10) then a1 = (14, −9): (9.8 − 3.92, 1 − 6.3 + 4.9).
    expect(hint([5.88, -0.4])).toContain('Check the sign of a₂');
    // μ and 1 − μ swapped: P(0.3) = (−0.6 + 0.72, 1 + 3.3 − 0.9).
    expect(hint([0.12, 3.4])).toContain('That is P(0.3)');
    // a0 left out: (2.52, 3.8 − 1).
    expect(hint([2.52, 2.8])).toContain('Add a₀ = P₀');
    // a1 = P2 − P0 = (6, 1), a2 not taken off: (4.2 + 3.92, 1 + 0.7 − 4.9).
    expect(hint([8.12, -3.2])).toContain('subtract a₂');
    // On the polygon: P1 + 0.4(P2 − P1) = (3, 3.2).
    expect(hint([3, 3.2])).toContain('polygon');
    expect(hint([1, 1])).toContain('Work through equations 2 and 3 again');
    expect(hint([NaN, 1])).toBe('Type every number.');
    expect(posed.working).toEqual({ ...posed.state, step: LAST_STEP });
  });

  it('steer: P₁ moved so the dot for μ = 0.7 lands on its target, seed 1', () => {
    const posed = pose('steer', 1);
    const construct = task(posed, 'construct');
    // μ1 = 0.5, μ = 0.7: weights w0 = (0.2)(−0.3)/0.5 = −0.12, w1 = (0.7)(−0.3)/(−0.25) = 0.84,
    // w2 = (0.7)(0.2)/0.5 = 0.28. P0 = (0, 3), P2 = (6, 2), P1 from (2, −1) to (1, 0):
    // target = (0.84·1 + 0.28·6, −0.12·3 + 0.28·2) = (2.52, 0.2);
    // from (2, −1): (0.84·2 + 1.68, −0.36 − 0.84 + 0.56) = (3.36, −0.64), 0.84·√2 = 1.188 away.
    expect(posed.prompt).toBe(
      'With μ₁ = 0.5, drag P₁ until the dot for μ = 0.7 sits at (2.52, 0.2), within 0.1.',
    );
    expect(posed.state.points).toEqual([
      [0, 3],
      [2, -1],
      [6, 2],
    ]);
    const before = construct.check(posed.state);
    expect(before.correct).toBe(false);
    expect(before.message).toContain('P(0.7) is at (3.36, −0.64), 1.188 from (2.52, 0.2)');
    expect(before.message).toContain('0.84 times as far as P₁');
    expect(construct.solution.points[1]).toEqual([1, 0]);
    expect(construct.check(construct.solution).correct).toBe(true);
    const withP1 = (p1: Point) => ({ ...posed.state, points: [[0, 3], p1, [6, 2]] });
    // 0.1 off in x moves the dot 0.084: within 0.1; 0.2 off moves it 0.168: not.
    expect(construct.check(withP1([1.1, 0])).correct).toBe(true);
    expect(construct.check(withP1([1.2, 0])).correct).toBe(false);
    const p0Moved = {
      ...construct.solution,
      points: [
        [0, 2.5],
        [1, 0],
        [6, 2],
      ],
    };
    expect(construct.check(p0Moved).message).toBe('Move only P₁: put P₀ back at (0, 3).');
    expect(construct.check({ ...construct.solution, mu: 0.4 }).message).toContain(
      'Put μ₁ back at 0.5',
    );
    // The posed figure draws the curve and its dots, with the dot at μ = 0.7 off the target.
    expect(derive(posed.state).shown.name).toBe('ticks');
  });

  it('agrees with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });

  it('every seed: steps the script has, points neither on one line nor repeated', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        for (const e of exercises) {
          const posed = e.pose(seed, defaults);
          expect(posed.working.step).toBe(LAST_STEP);
          expect(degenerate(posed.state.points).collinear).toBe(false);
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
        expect(derive(posed.state).parametric.current).toBeNull();
      }),
    );
  });

  it('every seed: compute refuses answers 2 tolerances off', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const number = task(pose('compute', seed), 'number');
        const off = number.answer.map((v) => v + 2 * number.tolerance);
        expect(number.check(off).correct).toBe(false);
      }),
    );
  });

  it('every seed: steer’s target and P₁ are on the figure, its tolerance a finger’s reach', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('steer', seed);
        const { solution } = task(posed, 'construct');
        const view = frame(posed.state);
        // The target (in the prompt) and where P1 must be dragged are both on the opening figure.
        const target = posed.prompt.match(/sits at \((−?[\d.]+), (−?[\d.]+)\)/)!;
        const [x, y] = [target[1], target[2]].map((v) => Number(v.replace('−', '-')));
        expect(inside([x, y], view)).toBe(true);
        expect(inside(solution.points[1], view)).toBe(true);
        // A finger's reach: about 1–2% of the figure's span.
        const share = STEER_TOLERANCE / Math.max(view.maxX - view.minX, view.maxY - view.minY);
        expect(share).toBeGreaterThan(0.01);
        expect(share).toBeLessThan(0.025);
      }),
    );
  });
});
