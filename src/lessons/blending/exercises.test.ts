import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/blending';
import { defaultsOf } from '../../app/urlState';
import type { ConstructTask, NumberTask, PointTask, Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import { exercises } from './exercises';
import lesson from './lesson';
import type { BlendingModel } from './model';
import { type BlendingState, schema } from './state';

const defaults = defaultsOf(schema);
const derive = (s: BlendingState) => lesson.derive(s) as BlendingModel;
const pose = (id: string, seed: number): Posed<BlendingState> =>
  exercises.find((e) => e.id === id)!.pose(seed, defaults);
const numberTask = (posed: Posed<BlendingState>) => posed.task as NumberTask;
const pointTask = (posed: Posed<BlendingState>) => posed.task as PointTask;
const constructTask = (posed: Posed<BlendingState>) => posed.task as ConstructTask<BlendingState>;
/** C(n, i) μⁱ (1 − μ)ⁿ⁻ⁱ, written out again so the tests do not lean on src/math. */
const factorial = (k: number): number => (k <= 1 ? 1 : k * factorial(k - 1));
const weightOf = (n: number, i: number, mu: number) =>
  (factorial(n) / (factorial(i) * factorial(n - i))) * mu ** i * (1 - mu) ** (n - i);
/** The posed figure shows neither a weight, nor a function, nor P(μ), and its cursor is at 0. */
const hidesTheAnswer = (state: BlendingState) => {
  const { drawn } = derive(state);
  return (
    state.mu === 0 &&
    drawn.bernstein === 0 &&
    drawn.weights === 0 &&
    !drawn.point &&
    !drawn.curve &&
    state.comparison === 'none'
  );
};

describe('the blending exercises', () => {
  it('are the lesson’s, and pass the kit’s checks, P(μ) inside the polygon’s box', () => {
    expect(lesson.exercises).toBe(exercises);
    // The curve's point among its control points; the plot's top is checked on its own below.
    const inFigure = (state: BlendingState, [x, y]: Point, figure: string) => {
      if (figure !== 'curve') return true;
      const box = boundsOf(state.p);
      return x >= box.minX && x <= box.maxX && y >= box.minY && y <= box.maxY;
    };
    checkExercises(exercises, defaults, { runs: 300, inFigure });
  });

  it('agree with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});

describe('a blending function’s value', () => {
  it('seed 4: W(5, 2, 0.25) = 10·(1/4)²·(3/4)³ = 270/1024, and each slip its hint', () => {
    const posed = pose('weight', 4);
    expect(posed.prompt).toBe(
      'Compute the blending function W(5, 2, 0.25), the weight of P₂ at μ = 0.25 on a curve of degree N = 5 (to 3 decimals).',
    );
    expect(posed.state.p).toHaveLength(6);
    const task = numberTask(posed);
    expect(task.fields).toEqual(['W(5, 2, 0.25)']);
    expect(task.answer[0]).toBeCloseTo(270 / 1024, 14);
    expect(task.check([0.264]).correct).toBe(true);
    expect(task.check([0.27]).correct).toBe(false);
    // Swapped: 10·(3/4)²·(1/4)³ = 90/1024 = 0.0879.
    expect(task.check([0.088]).message).toContain('you swapped μ and 1 − μ');
    // No binomial: (1/4)²·(3/4)³ = 27/1024 = 0.0264.
    expect(task.check([0.026]).message).toContain('C(5, 2) = 10');
    // Six points counted as the degree: W(6, 2, 1/4) = 15·(1/16)·(81/256) = 1215/4096 = 0.2966.
    expect(task.check([0.297]).message).toContain('N is the degree, 5');
    // The neighbour P₁: W(5, 1, 1/4) = 5·(1/4)·(81/256) = 405/1024 = 0.3955.
    expect(task.check([0.396]).message).toContain('That is W(5, 1, μ), the weight of P₁');
    expect(task.check([0.5]).message).toContain('W(5, 2, μ) = 10·μ²·(1 − μ)³');
  });

  it('opens with nothing weighted, and its working ends on every weight at μ', () => {
    const posed = pose('weight', 4);
    expect(hidesTheAnswer(posed.state)).toBe(true);
    const working = derive(posed.working);
    expect(working.state.mu).toBe(0.25);
    expect(working.drawn.weights).toBe(6);
    expect(working.weights[2]).toBeCloseTo(270 / 1024, 14);
  });

  it('every seed: the answer is the formula worked out, hidden when the exercise opens', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('weight', seed);
        const task = numberTask(posed);
        const [n, i, mu] = /W\((\d), (\d), ([\d.]+)\)/.exec(posed.prompt)!.slice(1).map(Number);
        expect(posed.state.p).toHaveLength(n + 1);
        expect(task.answer[0]).toBeCloseTo(weightOf(n, i, mu), 12);
        expect(hidesTheAnswer(posed.state)).toBe(true);
      }),
      { numRuns: 300 },
    ));
});

describe('where is P(μ)?', () => {
  it('seed 8: P(0.5) of (0, 0), (2, 4), (4, 1) is (2, 2.25), worked by hand', () => {
    const posed = pose('blend', 8);
    expect(posed.state.p).toEqual([
      [0, 0],
      [2, 4],
      [4, 1],
    ]);
    expect(posed.prompt).toContain('P(0.5) = Σ W(2, i, 0.5)·Pᵢ');
    // Weights 1/4, 1/2, 1/4: (0 + 2·2 + 4)/4 = 2, (0 + 2·4 + 1)/4 = 2.25.
    const task = pointTask(posed);
    expect(task.figure).toBe('curve');
    expect(task.answer[0]).toBeCloseTo(2, 14);
    expect(task.answer[1]).toBeCloseTo(2.25, 14);
    expect(task.check([2.1, 2.3]).correct).toBe(true);
    // The polygon's middle corner is not the blend.
    const wrong = task.check([2, 4]);
    expect(wrong.correct).toBe(false);
    expect(wrong.message).toContain('the weights of P₀ … P₂ are 0.25, 0.5, 0.25');
    expect(hidesTheAnswer(posed.state)).toBe(true);
    expect(derive(posed.working).drawn.point).toBe(true);
  });

  it('every seed: on the curve’s figure, hidden when the exercise opens', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('blend', seed);
        expect(pointTask(posed).figure).toBe('curve');
        expect(hidesTheAnswer(posed.state)).toBe(true);
      }),
      { numRuns: 300 },
    ));
});

describe('where does a weight peak?', () => {
  it('seed 6: W(4, 1, μ) peaks at μ = 1/4, at 4·(1/4)·(3/4)³ = 0.421875', () => {
    const posed = pose('peak', 6);
    expect(posed.prompt).toContain('W(4, 1, μ)');
    const task = pointTask(posed);
    expect(task.figure).toBe('blending');
    expect(task.answer[0]).toBe(0.25);
    expect(task.answer[1]).toBeCloseTo(0.421875, 14);
    expect(task.check([0.27, 0.4]).correct).toBe(true);
    expect(task.check([0.25, 0.3]).message).toContain('Right μ; the top is as high as');
    expect(task.check([0.5, 0.3]).message).toContain('μ : (1 − μ) = 1 : 3');
    expect(hidesTheAnswer(posed.state)).toBe(true);
    // The working draws the functions, W(4, 1, μ) among them, with the cursor on its top.
    const working = derive(posed.working);
    expect(working.drawn.bernstein).toBe(5);
    expect(working.weights[1]).toBeCloseTo(0.421875, 14);
  });

  it('every seed: on the plot, at i/N, as high as the formula', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('peak', seed);
        const task = pointTask(posed);
        const [n, i] = /W\((\d), (\d), μ\)/.exec(posed.prompt)!.slice(1).map(Number);
        expect(task.answer[0]).toBeCloseTo(i / n, 14);
        expect(task.answer[1]).toBeCloseTo(weightOf(n, i, i / n), 12);
        // Every W(N, i, μ) of 0 < i < N is below W(2, 1, 1/2) = 1/2 and above 0.
        expect(task.answer[0]).toBeGreaterThan(0);
        expect(task.answer[0]).toBeLessThan(1);
        expect(task.answer[1]).toBeGreaterThan(0);
        expect(task.answer[1]).toBeLessThanOrEqual(0.5);
        expect(hidesTheAnswer(posed.state)).toBe(true);
      }),
      { numRuns: 300 },
    ));
});

describe('where two points pull equally', () => {
  it('seed 6: (1 − μ)⁴ = 4μ(1 − μ)³ at μ = 0.2, from the cursor at 0.9', () => {
    const posed = pose('crossing', 6);
    expect(posed.prompt).toBe(
      'Drag the cursor μ on the plot to where P₀ and P₁ pull equally hard, W(4, 0, μ) = W(4, 1, μ) (within 5% of each other).',
    );
    const task = constructTask(posed);
    expect(task.solution.mu).toBe(0.2);
    // Both 0.8⁴ = 4·0.2·0.8³ = 0.4096.
    expect(task.check(task.solution)).toEqual({
      correct: true,
      message: 'Correct: at μ = 0.2, W(4, 0, μ) = 0.41 and W(4, 1, μ) = 0.41.',
    });
    // At 0.9: 0.1⁴ = 0.0001 and 4·0.9·0.1³ = 0.0036.
    expect(task.check(posed.state).message).toBe(
      'Not yet: at μ = 0.9, W(4, 0, μ) = 0 and W(4, 1, μ) = 0.004. P₁ still pulls harder, so move μ left.',
    );
    // At 0.1: 0.9⁴ = 0.6561 and 4·0.1·0.9³ = 0.2916: P₀ heavier, go right.
    expect(task.check({ ...posed.state, mu: 0.1 }).message).toContain(
      'P₀ still pulls harder, so move μ right',
    );
    // 0.205: 0.3994 and 0.4120, 3% apart; 0.21: 0.3895 and 0.4142, 6% apart.
    expect(task.check({ ...posed.state, mu: 0.205 }).correct).toBe(true);
    expect(task.check({ ...posed.state, mu: 0.21 }).correct).toBe(false);
    expect(task.check({ ...task.solution, p: task.solution.p.slice(1) }).message).toBe(
      'Keep N = 4: put back 5 control points (there are 4 now).',
    );
  });

  it('seed 8: both weights 0 at μ = 0 are not the crossing at μ = 2/3', () => {
    const posed = pose('crossing', 8);
    expect(posed.prompt).toContain('W(2, 1, μ) = W(2, 2, μ)');
    const task = constructTask(posed);
    // 2μ(1 − μ) = μ² at μ = 2/3.
    expect(task.solution.mu).toBeCloseTo(2 / 3, 4);
    const atZero = task.check({ ...posed.state, mu: 0 });
    expect(atZero.correct).toBe(false);
    expect(atZero.message).toContain('neither point pulls at all');
  });

  it('every seed: the solution survives a finger’s slip of 0.005, with every function drawn', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('crossing', seed);
        const task = constructTask(posed);
        const [n, i] = /W\((\d), (\d), μ\)/.exec(posed.prompt)!.slice(1).map(Number);
        // C(N, i)(1 − μ) = C(N, i + 1)μ: μ = (i + 1)/(N + 1).
        expect(task.solution.mu).toBeCloseTo((i + 1) / (n + 1), 4);
        for (const slip of [-0.005, 0.005])
          expect(task.check({ ...task.solution, mu: task.solution.mu + slip }).correct).toBe(true);
        expect(derive(posed.state).drawn.bernstein).toBe(n + 1);
      }),
      { numRuns: 300 },
    ));
});
