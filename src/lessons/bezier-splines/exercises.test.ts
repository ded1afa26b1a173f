import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import type { Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import {
  MIRROR_TOLERANCE,
  SECOND_TOLERANCE,
  SYSTEM_TOLERANCE,
  VELOCITY_TOLERANCE,
  exercises,
} from './exercises';
import data from '../../../tests/e2e/practice/bezier-splines';
import lesson from './lesson';
import type { BezierSplinesModel } from './model';
import { scripts } from './script';
import { type BezierSplinesState, normalize, schema } from './state';

type State = BezierSplinesState;
const defaults = defaultsOf(schema);
const derive = (s: State) => lesson.derive(s) as BezierSplinesModel;
const lastStep = (s: State) => lesson.steps!.count(s);
const main = lesson.figures.find((f) => f.id === 'main')!;
const pose = (id: string, seed: number) => exercises.find((e) => e.id === id)!.pose(seed, defaults);
const formulaAt = (s: State, step: number) => {
  const at = { ...s, step };
  return lesson.steps!.formula!(derive(at), at) ?? '';
};

function task<K extends 'point' | 'number' | 'construct'>(posed: Posed<State>, kind: K) {
  if (posed.task.kind !== kind) throw new Error(`a ${kind} task, not ${posed.task.kind}`);
  return posed.task as Extract<Posed<State>['task'], { kind: K }>;
}

/** Drags a handle of the main figure, as the browser test does. */
const drag = (s: State, handle: string, to: Point) => main.moveHandle!(s, handle, to, derive(s));

describe('the Bézier splines exercises', () => {
  it('are three, one of each kind, with their own ids', () => {
    expect(exercises.map((e) => e.kind).sort()).toEqual(['construct', 'number', 'point']);
    expect(new Set(exercises.map((e) => e.id)).size).toBe(exercises.length);
    expect(lesson.exercises).toBe(exercises);
  });

  it('pass the kit’s checks, bₖ within the points’ box widened by its width on each side', () => {
    const nearPoints = (state: State, [x, y]: Point) => {
      const box = boundsOf(state.points);
      const width = box.maxX - box.minX;
      return (
        x >= box.minX - width &&
        x <= box.maxX + width &&
        y >= box.minY - width &&
        y <= box.maxY + width
      );
    };
    checkExercises(exercises, defaults, { inFigure: nearPoints });
  });

  it('pose states the link can hold, in their part', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        for (const e of exercises) {
          const posed = e.pose(seed, defaults);
          for (const s of [posed.state, posed.working]) {
            expect(normalize(s).state).toEqual(s);
            expect(s.step).toBeLessThanOrEqual(lastStep(s));
            expect(s.part).toBe(posed.state.part);
          }
          expect(posed.working.step).toBe(0);
        }
      }),
      { numRuns: 60 },
    );
  });
});

describe('Where is bₖ of the C¹ quadratic spline?', () => {
  // Seed 1: p₀ (0, 1), p₁ (2, 0), p₂ (4, 1), p₃ (6, 2), p₄ (8, 2), b₀ = (0.5, 1), asked b₃.
  // b₁ = 2p₁ − b₀ = (3.5, −1), b₂ = 2p₂ − b₁ = (4.5, 3), b₃ = 2p₃ − b₂ = (7.5, 1).
  const posed = pose('mirror-control', 1);
  const point = task(posed, 'point');

  it('poses the points, b₀ and k, and bₖ by hand', () => {
    expect(posed.prompt).toContain('p₃ (6, 2)');
    expect(posed.prompt).toContain('b₀ = (0.5, 1)');
    expect(posed.prompt).toContain('Where is b₃');
    expect(point.answer).toEqual([7.5, 1]);
    expect(point.tolerance).toBe(MIRROR_TOLERANCE);
  });

  it('accepts b₃, rejects a point 0.75 off, and names the slips', () => {
    expect(point.check([7.4, 1.1]).correct).toBe(true);
    expect(point.check([7.5, 1.75]).correct).toBe(false);
    expect(point.check([4.5, 3]).message).toContain('That is b₂');
    expect(point.check([3.5, -1]).message).toContain('the joint of pieces 2 and 3');
    // The middle of p₃p₄ = (7, 2): as if every b were chosen like b₀.
    expect(point.check([7, 2]).message).toContain('Only b₀ is chosen');
    expect(point.check([0, 0]).message).toContain('Reflect one point at a time');
  });

  it('hides every b at the start; the working’s mirror step gives b₃ with its numbers', () => {
    const start = derive(posed.state);
    expect(start.shown.has('firstPiece')).toBe(false);
    expect(main.handles!(start).some((h) => h.id === 'b0')).toBe(false);
    const third = scripts.quadratic.stepOf(posed.working, 'mirror', 3);
    expect(formulaAt(posed.working, third)).toContain('b_{3} = 2p_{3} - b_{2}');
    expect(derive({ ...posed.working, step: third }).quadraticControls[3]).toEqual([7.5, 1]);
  });
});

describe('Solve the C² system through three points', () => {
  // Seed 1: p₀ = c₀ = (0, 2), p₁ = c₃ = (2, 3), p₂ = c₆ = (9, 5).
  // Natural ends: c₁ = (c₀ + c₂)/2, c₅ = (c₄ + c₆)/2; C¹: c₄ = 2c₃ − c₂;
  // C²: c₁ − 2c₂ + 2c₄ − c₅ = 0 ⇒ (c₀ − 3c₂ + 3c₄ − c₆)/2 = 0 ⇒ 6c₂ = c₀ + 6c₃ − c₆
  // = (0 + 12 − 9, 2 + 18 − 5) = (3, 15): c₂ = (0.5, 2.5).
  const posed = pose('c2-system', 1);
  const numbers = task(posed, 'number');

  it('poses the three points, and c₂ by hand', () => {
    expect(posed.prompt).toContain('p₀ (0, 2), p₁ (2, 3) and p₂ (9, 5)');
    expect(posed.state.points).toEqual([
      [0, 2],
      [2, 3],
      [9, 5],
    ]);
    expect(numbers.answer[0]).toBeCloseTo(0.5, 12);
    expect(numbers.answer[1]).toBeCloseTo(2.5, 12);
  });

  it('accepts two decimals, rejects c₂ a little off, and names each slip', () => {
    expect(numbers.check([0.5, 2.5]).correct).toBe(true);
    expect(numbers.check([0.5, 2.52]).correct).toBe(false);
    // c₄ = 2c₃ − c₂ = (3.5, 3.5).
    expect(numbers.check([3.5, 3.5]).message).toContain('That is c₄');
    // c₃ − (c₆ − c₀)/3 = (−1, 2): the 6 of 6c₂ missed.
    expect(numbers.check([-1, 2]).message).toContain('6c₂ = c₀ + 6c₃ − c₆');
    // c₃ − (c₆ − c₀)/2 = (−2.5, 1.5): the whole tangent.
    expect(numbers.check([-2.5, 1.5]).message).toContain('whole tangent');
    // c₁ = (c₀ + c₂)/2 = (0.25, 2.25).
    expect(numbers.check([0.25, 2.25]).message).toContain('That is c₁');
    expect(numbers.check([1, 1]).message).toContain('Write the 7 equations');
  });

  it('hides the system at the start; the working’s solution step shows c₂', () => {
    expect(derive(posed.state).shown.has('solution')).toBe(false);
    const solved = scripts.system.stepOf(posed.working, 'solution');
    expect(formulaAt(posed.working, solved)).toMatch(/c_\{2\} = \(0\.50,\\ 2\.50\)/);
  });

  it('has at most one decimal for every seed, and never passes c₂ off in x alone or at a slip', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const p = pose('c2-system', seed);
        const t = task(p, 'number');
        expect(t.check([t.answer[0] + 3 * SYSTEM_TOLERANCE, t.answer[1]]).correct).toBe(false);
        // c₂ = p₁ − (p₂ − p₀)/6 with p₂ − p₀ in multiples of 3: halves at most.
        t.answer.forEach((v) => expect(Math.abs(2 * v - Math.round(2 * v))).toBeLessThan(1e-9));
        // The slip c₄ = 2p₁ − c₂ is never the answer.
        const [, p1] = p.state.points;
        expect(t.check([2 * p1[0] - t.answer[0], 2 * p1[1] - t.answer[1]]).correct).toBe(false);
      }),
    );
  });
});

describe('Make a joint C²', () => {
  // Seed 1: c₀ (0, 0), c₁ (1, 2), c₂ (2, 3), c₃ (4, 4), c₆ (10, 2); posed c₄ (8, 6), c₅ (11, 7).
  // C¹: c₄ = 2c₃ − c₂ = (6, 5). C²: c₅ = c₁ − 2c₂ + 2c₄ = (1 − 4 + 12, 2 − 6 + 10) = (9, 6).
  // Posed: P′ left 3(c₃ − c₂) = (6, 3), right 3(c₄ − c₃) = (12, 6);
  // P″ left 6(c₁ − 2c₂ + c₃) = (6, 0), right 6(c₃ − 2c₄ + c₅) = (−6, −6).
  const posed = pose('c2-joint', 1);
  const construct = task(posed, 'construct');

  it('opens on the chain, not yet C¹, and says so with its numbers', () => {
    expect(posed.prompt).toContain('Keep c₁ (1, 2), c₂ (2, 3), c₃ (4, 4)');
    expect(posed.state.handBuilt).toEqual([
      [0, 0],
      [1, 2],
      [2, 3],
      [4, 4],
      [8, 6],
      [11, 7],
      [10, 2],
    ]);
    const verdict = construct.check(posed.state);
    expect(verdict.correct).toBe(false);
    expect(verdict.message).toContain('(6, 3) on the left and (12, 6) on the right');
    expect(verdict.message).toContain('(6, 0) and (−6, −6)');
  });

  it('passes once c₄ and c₅ are dragged to (6, 5) and (9, 6), and says what is still off on the way', () => {
    const ids = main.handles!(derive(posed.state)).map((h) => h.id);
    expect(ids).toEqual(expect.arrayContaining(['q4', 'q5']));
    const c1 = drag(posed.state, 'q4', [6, 5]);
    // C¹ now; P″ right 6(4 − 12 + 11, 4 − 10 + 7) = (18, 6), 13.4 from (6, 0).
    expect(construct.check(c1).message).toContain('C¹ holds, but P″ differs by 13.416');
    const c2 = drag(c1, 'q5', [9, 6]);
    expect(construct.check(c2).correct).toBe(true);
    // Within the tolerance of a finger: c₄ 0.1 off, c₅ 0.2 off.
    expect(construct.check(drag(drag(posed.state, 'q4', [6.1, 5]), 'q5', [9.2, 6.2])).correct).toBe(
      true,
    );
    expect(construct.check(drag(c2, 'q5', [9.6, 6])).correct).toBe(false);
  });

  it('wants the other points left alone', () => {
    const moved = drag(construct.solution, 'q3', [4.5, 4]);
    expect(construct.check(moved).message).toContain('Move only c₄ and c₅');
  });

  it('is solvable by two drags inside the posed figure, for every seed', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const p = pose('c2-joint', seed);
        const t = task(p, 'construct');
        const [c4, c5] = [t.solution.handBuilt[4], t.solution.handBuilt[5]];
        const box = main.bounds(derive(p.state));
        for (const q of [c4, c5]) {
          expect(q[0]).toBeGreaterThanOrEqual(box.minX);
          expect(q[0]).toBeLessThanOrEqual(box.maxX);
          expect(q[1]).toBeGreaterThanOrEqual(box.minY);
          expect(q[1]).toBeLessThanOrEqual(box.maxY);
        }
        expect(t.check(drag(drag(p.state, 'q4', c4), 'q5', c5)).correct).toBe(true);
        // C¹ alone is not enough: c₄ in place, c₅ where it opened.
        expect(t.check(drag(p.state, 'q4', c4)).correct).toBe(false);
        expect([VELOCITY_TOLERANCE, SECOND_TOLERANCE]).toEqual([0.5, 3]);
      }),
    );
  });
});

describe('the browser test’s practice data', () => {
  it('matches each posed prompt, and its answers pass where its wrong answers fail', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});
