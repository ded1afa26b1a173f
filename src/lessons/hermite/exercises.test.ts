import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/hermite';
import { defaultsOf } from '../../app/urlState';
import type { ExerciseSpec, Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import type { Bounds } from '../../render/projection';
import { BEZIER_TOLERANCE, GUESS_TOLERANCE, exercises } from './exercises';
import lesson from './lesson';
import type { HermiteModel } from './model';
import { type HermiteState, schema } from './state';

const defaults = defaultsOf(schema);
const exercise = (id: string) => exercises.find((e) => e.id === id) as ExerciseSpec<HermiteState>;
const pose = (id: string, seed: number) => exercise(id).pose(seed, defaults);
const derive = (s: HermiteState) => lesson.derive(s) as HermiteModel;
const lastStep = (s: HermiteState) => lesson.steps!.count(s);
/** The frame the app fits the patches' figure to. */
const frame = (s: HermiteState): Bounds =>
  lesson.figures.find((f) => f.id === 'patches')!.bounds(derive(s));
const inside = (p: readonly number[], b: Bounds) =>
  p[0] >= b.minX && p[0] <= b.maxX && p[1] >= b.minY && p[1] <= b.maxY;
const closeTo = (actual: readonly number[], expected: readonly number[]) =>
  expected.forEach((v, d) => expect(actual[d]).toBeCloseTo(v, 9));

function task<K extends 'point' | 'number' | 'construct'>(posed: Posed<HermiteState>, kind: K) {
  expect(posed.task.kind).toBe(kind);
  return posed.task as Extract<Posed<HermiteState>['task'], { kind: K }>;
}

describe('the Hermite lesson’s exercises', () => {
  it('are the lesson’s, and pass the kit’s checks, the point to guess inside the figure’s frame', () => {
    expect(lesson.exercises).toBe(exercises);
    checkExercises(exercises, defaults, {
      inFigure: (state, answer) => answer.every(Number.isFinite) && inside(answer, frame(state)),
    });
  });

  it('where: P(0.75) on one patch, seed 1, worked by hand', () => {
    const posed = pose('where', 1);
    expect(posed.prompt).toBe(
      'The patch leaves P₀ = (0, 1) with gradient D₀ = (6, 6) and arrives at P₁ = (4, 1) with D₁ = (3, 3). Where is P(0.75)?',
    );
    // μ = 0.75: H0 = 2(0.421875) − 3(0.5625) + 1 = 0.15625, H1 = 0.84375,
    // H2 = 0.421875 − 1.125 + 0.75 = 0.046875, H3 = 0.421875 − 0.5625 = −0.140625.
    // x = 0.84375·4 + 0.046875·6 − 0.140625·3 = 3.375 + 0.28125 − 0.421875 = 3.234375,
    // y = 0.15625 + 0.84375 + 0.28125 − 0.421875 = 0.859375.
    const point = task(posed, 'point');
    closeTo(point.answer, [3.234375, 0.859375]);
    expect(point.figure).toBe('patches');
    expect(point.check([3.3, 0.8]).correct).toBe(true);
    const wrong = point.check([3, 2]);
    expect(wrong.correct).toBe(false);
    expect(wrong.message).toContain('Hermite basis at μ = 0.75');
    // Step 1 draws the arrows but no patch, and at μ = 0 the panel's P(μ) is P₀.
    const opened = derive(posed.state);
    expect(opened.shown.has('gradients')).toBe(true);
    expect(opened.built).toBe(0);
    expect(opened.shown.has('pointAtMu')).toBe(false);
    expect(opened.patch.point).toEqual([0, 1]);
    // The working ends with P(0.75) drawn and written.
    const end = derive(posed.working);
    expect(end.shown.has('pointAtMu')).toBe(true);
    closeTo(end.patch.point, [3.234375, 0.859375]);
  });

  it('coefficients: a₂ and a₃ of patch 2, seed 7, with the hint for each slip', () => {
    const posed = pose('coefficients', 7);
    expect(posed.prompt).toBe(
      'Patch 2 runs from P₁ = (2, 3) to P₂ = (6, 1), with gradients D₁ = (1, 0) and D₂ = (3, −1). Compute a₂ and a₃ of its P(μ) = a₃μ³ + a₂μ² + a₁μ + a₀, each to 2 decimals (within 0.01).',
    );
    expect(posed.state.points[0]).toEqual([0, 0]);
    expect(posed.state.handGradients[0]).toEqual([2, 0]);
    // Equation 7 on (P1, D1, P2, D2): a2 = −3P1 − 2D1 + 3P2 − D2 = (−6 − 2 + 18 − 3, −9 − 0 + 3 + 1),
    // a3 = 2P1 + D1 − 2P2 + D2 = (4 + 1 − 12 + 3, 6 + 0 − 2 − 1).
    const number = task(posed, 'number');
    expect(number.fields).toEqual(['a₂ x', 'a₂ y', 'a₃ x', 'a₃ y']);
    expect(number.answer).toEqual([7, -5, -4, 3]);
    expect(number.check([7, -5, -4, 3])).toEqual({ correct: true, message: 'Correct.' });
    expect(number.check([7.005, -5, -4, 3.005]).correct).toBe(true);
    const hint = (values: number[]) => number.check(values).message;
    // Data as (P1, P2, D1, D2): a2 = −3P1 − 2P2 + 3D1 − D2 = (−6 − 12 + 3 − 3, −9 − 2 + 0 + 1),
    // a3 = 2P1 + P2 − 2D1 + D2 = (4 + 6 − 2 + 3, 6 + 1 − 0 − 1).
    expect(hint([-18, -10, 11, 6])).toContain('the lecture’s order P₁, D₁, P₂, D₂');
    expect(hint([-4, 3, 7, -5])).toContain('You swapped a₂ and a₃');
    // Patch 1 (P0 = (0, 0), D0 = (2, 0), P1, D1): a2 = 3(2, 3) − (4, 0) − (1, 0), a3 = 2(−2, −3) + (3, 0).
    expect(hint([1, 9, -1, -6])).toContain('That is patch 1');
    // The arrows D/3: a2 = 3(4, −2) − 2(1, 0)/3 − (3, −1)/3 = (31/3, −17/3), a3 = 2(−4, 2) + (4, −1)/3.
    expect(hint([31 / 3, -17 / 3, -20 / 3, 11 / 3])).toContain('use D₁ and D₂ themselves');
    expect(hint([0, 0, 0, 0])).toContain('Multiply the rows');
    // The opening figure is about patch 1 (its numbers in the panel); the working solves patch 2.
    expect(derive(posed.state).patch.index).toBe(0);
    expect(derive(posed.state).built).toBe(0);
    const working = derive({ ...posed.working, step: 5 });
    expect(working.shown.is('patch')).toBe(true);
    expect(working.patch.index).toBe(1);
    closeTo(working.patch.coefficients[2], [7, -5]);
    closeTo(working.patch.coefficients[3], [-4, 3]);
  });

  it('bezier: the gradients that make the patch a given Bézier curve, seed 1', () => {
    const posed = pose('bezier', 1);
    expect(posed.prompt).toBe(
      'Drag the gradients’ tips until this patch is the cubic Bézier curve with B₁ = (1, 3) and B₂ = (3, 1), each within 0.15.',
    );
    // P0 = (0, 1), P1 = (5, 0), opened with D0 = (6, 9), D1 = (6, −6):
    // B1 = P0 + D0/3 = (2, 4), √2 from (1, 3); B2 = P1 − D1/3 = (3, 2), 1 from (3, 1).
    expect(posed.state.points).toEqual([
      [0, 1],
      [5, 0],
    ]);
    expect(posed.state.handGradients).toEqual([
      [6, 9],
      [6, -6],
    ]);
    const construct = task(posed, 'construct');
    const before = construct.check(posed.state);
    expect(before.correct).toBe(false);
    expect(before.message).toContain('is at (2, 4), 1.414 from (1, 3)');
    expect(before.message).toContain('is at (3, 2), 1 from (3, 1)');
    expect(before.message).toContain('mirrored through P₁');
    // D0 = 3(B1 − B0) = (3, 6), D1 = 3(B3 − B2) = (6, −3).
    expect(construct.solution.handGradients).toEqual([
      [3, 6],
      [6, -3],
    ]);
    expect(construct.check(construct.solution).correct).toBe(true);
    const withGradients = (d1: Point) => ({ ...posed.state, handGradients: [[3, 6], d1] });
    // D1 0.3 off moves B2 by 0.1 (within 0.15); 0.6 off moves it 0.2 (not).
    expect(construct.check(withGradients([6.3, -3])).correct).toBe(true);
    const half = construct.check(withGradients([6.6, -3]));
    expect(half.correct).toBe(false);
    expect(half.message).not.toContain('B₁ = P₀');
    expect(half.message).toContain('0.2 from (3, 1)');
    const p1Moved = {
      ...construct.solution,
      points: [
        [0, 1],
        [5, 1],
      ],
    };
    expect(construct.check(p1Moved).message).toContain('put it back at (5, 0)');
    // In Catmull-Rom mode two points have zero gradients: B1 = B0, not the target.
    expect(construct.check({ ...construct.solution, mode: 'catmull-rom' }).correct).toBe(false);
    // The opening figure shows the patch and the tips to drag.
    const opened = derive(posed.state);
    expect(opened.built).toBe(1);
    expect(lesson.figures[0].handles!(opened).map((h) => h.id)).toEqual(['d0', 'p0', 'd1', 'p1']);
    expect(posed.working.bezier).toBe(true);
  });

  it('agrees with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });

  it('every seed: workings walked to their end, opening figures without a note', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        for (const e of exercises) {
          const posed = e.pose(seed, defaults);
          expect(posed.working.step).toBe(lastStep(posed.working));
          expect(derive(posed.state).note).toBeNull();
        }
      }),
    );
  });

  it('every seed: where is hidden at step 1, with a strict tolerance', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('where', seed);
        expect(task(posed, 'point').tolerance).toBe(GUESS_TOLERANCE);
        expect(derive(posed.state).built).toBe(0);
      }),
    );
  });

  it('every seed: coefficients refuses answers 2 tolerances off, not shown when it opens', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('coefficients', seed);
        const number = task(posed, 'number');
        const off = number.answer.map((v) => v - 2 * number.tolerance);
        expect(number.check(off).correct).toBe(false);
        expect(derive(posed.state).patch.index).toBe(0);
      }),
    );
  });

  it('every seed: bezier’s tips to drag are on the figure, its tolerance a finger’s reach', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('bezier', seed);
        const { solution } = task(posed, 'construct');
        const view = frame(posed.state);
        // Where the tips must be dragged to is on the figure as it opens.
        derive(solution).tips.forEach((tip) => expect(inside(tip, view)).toBe(true));
        // A finger's reach: about 1–2% of the figure's span.
        const share = BEZIER_TOLERANCE / Math.max(view.maxX - view.minX, view.maxY - view.minY);
        expect(share).toBeGreaterThan(0.008);
        expect(share).toBeLessThan(0.025);
      }),
    );
  });
});
