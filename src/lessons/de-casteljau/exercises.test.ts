import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/de-casteljau';
import { defaultsOf } from '../../app/urlState';
import type { ConstructTask, NumberTask, PointTask, Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import { exercises } from './exercises';
import lesson from './lesson';
import type { DeCasteljauModel } from './model';
import { type DeCasteljauState, schema } from './state';

const defaults = defaultsOf(schema);
const derive = (s: DeCasteljauState) => lesson.derive(s) as DeCasteljauModel;
const pose = (id: string, seed: number): Posed<DeCasteljauState> =>
  exercises.find((e) => e.id === id)!.pose(seed, defaults);
const numberTask = (posed: Posed<DeCasteljauState>) => posed.task as NumberTask;
const pointTask = (posed: Posed<DeCasteljauState>) => posed.task as PointTask;
const constructTask = (posed: Posed<DeCasteljauState>) =>
  posed.task as ConstructTask<DeCasteljauState>;
/** One cut of an edge: (1 − t)·a + t·b, written out again so the tests do not lean on src/math. */
const cut = (a: readonly number[], b: readonly number[], t: number) =>
  a.map((v, d) => (1 - t) * v + t * b[d]);

describe('the de Casteljau exercises', () => {
  it('are the lesson’s, and pass the kit’s checks, P(t) inside the polygon’s box', () => {
    expect(lesson.exercises).toBe(exercises);
    const inBox = (state: DeCasteljauState, [x, y]: Point) => {
      const box = boundsOf(state.p);
      return x >= box.minX && x <= box.maxX && y >= box.minY && y <= box.maxY;
    };
    checkExercises(exercises, defaults, { runs: 300, inFigure: inBox });
  });

  it('agree with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});

describe('where is P(t)?', () => {
  it('seed 2: P(0.75) of (0, 0), (0, 3), (5, 3), (5, 0) is (4.21875, 1.6875), worked by hand', () => {
    const posed = pose('where-is-p', 2);
    expect(posed.state.p).toEqual([
      [0, 0],
      [0, 3],
      [5, 3],
      [5, 0],
    ]);
    expect(posed.state.t).toBe(0.75);
    expect(posed.prompt).toContain('P(0.75)');
    // Weights at 0.75: (1/4)³ = 1/64, 3·(3/4)(1/4)² = 9/64, 3·(3/4)²(1/4) = 27/64, (3/4)³ = 27/64.
    // x = (27·5 + 27·5)/64 = 270/64 = 4.21875; y = (9·3 + 27·3)/64 = 108/64 = 1.6875.
    const task = pointTask(posed);
    expect(task.figure).toBe('construction');
    expect(task.answer[0]).toBeCloseTo(4.21875, 12);
    expect(task.answer[1]).toBeCloseTo(1.6875, 12);
    expect(task.check([4.2, 1.7]).correct).toBe(true);
    const far = task.check([3, 2.5]);
    expect(far.correct).toBe(false);
    expect(far.message).toContain('Level 1 cuts every edge at t = 0.75');
  });

  it('opens at the polygon (no level, no curve), and its working ends on P(t)', () => {
    const posed = pose('where-is-p', 2);
    const shown = derive(posed.state).shown;
    expect(shown.count('level')).toBe(0);
    expect(shown.has('curve')).toBe(false);
    expect(shown.has('polygon')).toBe(true);
    const working = derive(posed.working);
    expect(working.shown.last).toBe(true);
    expect(working.levels[3][0][0]).toBeCloseTo(4.21875, 12);
  });

  it('every seed: no level drawn when the exercise opens', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('where-is-p', seed);
        expect(derive(posed.state).shown.count('level')).toBe(0);
      }),
      { numRuns: 300 },
    ));
});

describe('a point of the construction', () => {
  it('seed 2: P₂,₀ at t = 0.3 is (0.36, 1.69), worked by hand', () => {
    const posed = pose('level-point', 2);
    expect(posed.prompt).toBe(
      'For P₀ = (0, 1), P₁ = (0, 2), P₂ = (4, 4), P₃ = (6, 0) and t = 0.3, compute the de Casteljau point P₂,₀ (x and y, to 2 decimals).',
    );
    // Level 1: P₁,₀ = 0.7·(0, 1) + 0.3·(0, 2) = (0, 1.3); P₁,₁ = 0.7·(0, 2) + 0.3·(4, 4) = (1.2, 2.6).
    // Level 2: P₂,₀ = 0.7·(0, 1.3) + 0.3·(1.2, 2.6) = (0.36, 0.91 + 0.78) = (0.36, 1.69).
    const task = numberTask(posed);
    expect(task.tolerance).toBe(0.01);
    expect(task.answer[0]).toBeCloseTo(0.36, 12);
    expect(task.answer[1]).toBeCloseTo(1.69, 12);
    expect(task.check([0.36, 1.69])).toEqual({ correct: true, message: 'Correct.' });
    expect(task.check([0.4, 1.7]).correct).toBe(false);
    // t and 1 − t swapped: P₁,₀ = 0.3·(0, 1) + 0.7·(0, 2) = (0, 1.7), P₁,₁ = 0.3·(0, 2) + 0.7·(4, 4) = (2.8, 3.4),
    // P₂,₀ = 0.3·(0, 1.7) + 0.7·(2.8, 3.4) = (1.96, 2.89).
    expect(task.check([1.96, 2.89]).message).toContain('you swapped t and 1 − t');
    // Stopped a level early: P₁,₁ = (1.2, 2.6).
    expect(task.check([1.2, 2.6]).message).toContain('That is P₁,₁, a point of level 1');
    // Cut in the middle: P₁,₀ = (0, 1.5), P₁,₁ = (2, 3), P₂,₀ = (1, 2.25).
    expect(task.check([1, 2.25]).message).toContain('cuts every edge in the middle');
    expect(task.check([Number.NaN, 1]).message).toBe('Type every number.');
  });

  it('a neighbour on the same level gets its own hint', () => {
    // Seed 1: P₂,₁ of (0, 1), (0, 3), (5, 4), (5, 1) at t = 0.7. Its neighbour P₂,₀:
    // P₁,₀ = (0, 2.4), P₁,₁ = (3.5, 3.7), P₂,₀ = 0.3·(0, 2.4) + 0.7·(3.5, 3.7) = (2.45, 3.31).
    const task = numberTask(pose('level-point', 1));
    expect(task.check([2.45, 3.31]).message).toContain('That is P₂,₀, its neighbour on level 2');
  });

  it('opens at the polygon, and its working walks every level', () => {
    const posed = pose('level-point', 2);
    expect(derive(posed.state).shown.count('level')).toBe(0);
    const working = derive(posed.working);
    expect(working.shown.count('level')).toBe(3);
    expect(working.levels[2][0][1]).toBeCloseTo(1.69, 12);
  });

  it('every seed: the answer is the named point, cut level by level by hand', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('level-point', seed);
        const task = numberTask(posed);
        // The named point, cut level by level from the posed points.
        const [, r, i] = /P([₁₂]),([₀₁₂])/.exec(posed.prompt)!.map((c) => '₀₁₂'.indexOf(c));
        let level = posed.state.p;
        for (let k = 0; k < r; k++)
          level = level.slice(1).map((q, j) => cut(level[j], q, posed.state.t));
        expect(task.answer[0]).toBeCloseTo(level[i][0], 10);
        expect(task.answer[1]).toBeCloseTo(level[i][1], 10);
      }),
      { numRuns: 300 },
    ));
});

describe('split the curve in two', () => {
  it('seed 2: the right half at t = 0.3 runs P₃,₀, P₂,₁, …; its second point P₂,₁ = (2.22, 2.66), worked by hand', () => {
    const posed = pose('split-half', 2);
    expect(posed.prompt).toBe(
      'Split the curve of P₀ = (0, 1), P₁ = (0, 2), P₂ = (4, 4), P₃ = (6, 0) at t = 0.3: what is the second control point of the right half, from P(t) to P₃? Give x and y to 2 decimals.',
    );
    // Level 1: P₁,₀ = (0, 1.3), P₁,₁ = (1.2, 2.6), P₁,₂ = 0.7·(4, 4) + 0.3·(6, 0) = (4.6, 2.8).
    // Level 2: P₂,₁ = 0.7·(1.2, 2.6) + 0.3·(4.6, 2.8) = (0.84 + 1.38, 1.82 + 0.84) = (2.22, 2.66).
    const task = numberTask(posed);
    expect(task.answer[0]).toBeCloseTo(2.22, 12);
    expect(task.answer[1]).toBeCloseTo(2.66, 12);
    expect(task.check([2.22, 2.66]).correct).toBe(true);
    expect(task.check([2.3, 2.66]).correct).toBe(false);
    // The left half's second point, P₁,₀.
    expect(task.check([0, 1.3]).message).toContain('That is the second point of the left half');
    // Counted from P₃: P₁,₂.
    expect(task.check([4.6, 2.8]).message).toContain('That counts from the wrong end');
    // P₁ itself.
    expect(task.check([0, 2]).message).toContain('That is P₁ itself');
    // t and 1 − t swapped: P₁,₁ = (2.8, 3.4), P₁,₂ = (5.4, 1.2), P₂,₁ = 0.3·(2.8, 3.4) + 0.7·(5.4, 1.2) = (4.62, 1.86).
    expect(task.check([4.62, 1.86]).message).toContain('you swapped t and 1 − t');
    expect(task.check([1, 1]).message).toContain('this one is P₂,₁, a point of level 2');
  });

  it('opens at the polygon unsplit; its working shows the two halves', () => {
    const posed = pose('split-half', 2);
    expect(posed.state.mode).toBe('construction');
    expect(derive(posed.state).shown.count('level')).toBe(0);
    const working = derive(posed.working);
    expect(posed.working.mode).toBe('halves');
    expect(working.shown.last).toBe(true);
    expect(working.right[1][0]).toBeCloseTo(2.22, 12);
  });

  it('every seed: the point is the level’s first (left) or last (right) point, cut again by hand', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('split-half', seed);
        const task = numberTask(posed);
        const j = posed.prompt.includes('second control point') ? 1 : 2;
        const right = posed.prompt.includes('right half');
        let level = posed.state.p;
        const levels = [level];
        while (level.length > 1) {
          level = level.slice(1).map((q, k) => cut(level[k], q, posed.state.t));
          levels.push(level);
        }
        // Left: the first point of level j; right: the last point of level 3 − j.
        const expected = right ? levels[3 - j][j] : levels[j][0];
        expect(task.answer[0]).toBeCloseTo(expected[0], 10);
        expect(task.answer[1]).toBeCloseTo(expected[1], 10);
        // 3× the tolerance below (the kit checks above).
        expect(task.check(task.answer.map((v) => v - 3 * task.tolerance)).correct).toBe(false);
      }),
      { numRuns: 300 },
    ));
});

describe('make the curve pass through X', () => {
  it('seed 5: P₂ = (5.8667, 2.1333) puts P(0.5) on X = (3.7, 1.8), worked by hand', () => {
    const posed = pose('through-point', 5);
    expect(posed.prompt).toBe(
      'Move only P₂ so that the curve passes through X = (3.7, 1.8) at t = 0.5, within 0.08.',
    );
    expect(posed.state.p).toEqual([
      [0, 1],
      [2, 2],
      [4, 2],
      [6, 1],
    ]);
    // Now P(0.5) = (P₀ + 3P₁ + 3P₂ + P₃)/8 = ((0 + 6 + 12 + 6)/8, (1 + 6 + 6 + 1)/8) = (3, 1.75).
    // X − P(0.5) = (0.7, 0.05), and P(0.5) follows P₂ by W(3, 2, 0.5) = 3/8:
    // P₂ moves by (0.7, 0.05)·8/3 = (1.8667, 0.1333), to (5.8667, 2.1333).
    const task = constructTask(posed);
    const moved = task.solution.p[2];
    expect(moved[0]).toBeCloseTo(4 + (0.7 * 8) / 3, 10);
    expect(moved[1]).toBeCloseTo(2 + (0.05 * 8) / 3, 10);
    expect(task.check(task.solution).correct).toBe(true);
    const before = task.check(posed.state);
    expect(before.correct).toBe(false);
    expect(before.message).toContain('P(0.5) is at (3, 1.75), 0.702 from X = (3.7, 1.8)');
    expect(before.message).toContain('move P₂ by about (1.867, 0.133)');
  });

  it('says what else is off: another point moved, a point added', () => {
    const posed = pose('through-point', 5);
    const task = constructTask(posed);
    const shifted = task.solution.p.map((q, i) => (i === 1 ? [q[0], q[1] + 1] : q));
    expect(task.check({ ...task.solution, p: shifted }).message).toBe(
      'Move only P₂: P₁ belongs at (2, 2).',
    );
    expect(task.check({ ...task.solution, p: [...task.solution.p, [7, 0]] }).message).toContain(
      'Keep the four control points',
    );
    // The slider is not the question: P(0.5) is checked whatever t shows.
    expect(task.check({ ...task.solution, t: 0.2 }).correct).toBe(true);
    // Half-way there is not there: P(0.5) is 0.35 from X.
    const half = posed.state.p.map((q, i) => (i === 2 ? [q[0] + 0.9333, q[1] + 0.0667] : q));
    expect(task.check({ ...posed.state, p: half }).correct).toBe(false);
  });

  it('opens with the whole construction shown, and the solution is in reach of a finger', () => {
    const posed = pose('through-point', 5);
    expect(derive(posed.state).shown.last).toBe(true);
    const task = constructTask(posed);
    // 0.08 is 1.3% of the polygon's 6 units; P₂ may be off by 0.08/W(3, 2, 0.5) = 0.21 either way.
    const near = task.solution.p.map((q, i) => (i === 2 ? [q[0] + 0.15, q[1] - 0.1] : q));
    expect(task.check({ ...task.solution, p: near }).correct).toBe(true);
  });

  it('every seed: the point moved stays near the figure, and Show me ends on the solution', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('through-point', seed);
        const task = constructTask(posed);
        const xs = posed.state.p.map((q) => q[0]);
        const ys = posed.state.p.map((q) => q[1]);
        for (const q of task.solution.p) {
          expect(q[0]).toBeGreaterThanOrEqual(Math.min(...xs) - 0.3);
          expect(q[0]).toBeLessThanOrEqual(Math.max(...xs) + 0.3);
          expect(q[1]).toBeGreaterThanOrEqual(Math.min(...ys) - 0.3);
          expect(q[1]).toBeLessThanOrEqual(Math.max(...ys) + 0.3);
        }
        expect(posed.working).toEqual(task.solution);
      }),
      { numRuns: 300 },
    ));
});
