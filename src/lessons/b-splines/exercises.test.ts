import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/b-splines';
import { defaultsOf } from '../../app/urlState';
import type { Posed, Task } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Revealed } from '../../kit/script';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import { exercises } from './exercises';
import { knotFigure } from './knotFigure';
import lesson from './lesson';
import type { BSplineModel } from './model';
import type { Reveal } from './scripts';
import { type BSplineState, normalize, schema } from './state';

// Each exercise for one seed worked by hand, then every seed: solvable, the
// posed figure not yet showing the answer, "Show me" reaching it.

const defaults = normalize(defaultsOf(schema)).state;
const derive = (s: BSplineState) => lesson.derive(s) as BSplineModel;
const lastStep = (s: BSplineState) => lesson.steps!.count(s);
/** What a state's step shows, by the names of every scene family. */
const shownIn = (s: BSplineState) => derive(s).shown as Revealed<Reveal>;
const byId = (id: string) => exercises.find((e) => e.id === id)!;
const gap = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);

function taskOf<K extends Task<BSplineState>['kind']>(posed: Posed<BSplineState>, kind: K) {
  if (posed.task.kind !== kind) throw new Error(`a ${posed.task.kind} task, not ${kind}`);
  return posed.task as Extract<Task<BSplineState>, { kind: K }>;
}

describe('Where is a point of a segment? (seed 1)', () => {
  const posed = byId('segment-point').pose(1, defaults);
  const task = taskOf(posed, 'point');

  it('poses Q₃(0.5) of seven zigzag points, and the answer is P₀ … P₃ weighted 1, 23, 23, 1 over 48', () => {
    expect(posed.state.points).toEqual([
      [0, 4],
      [3, 1],
      [4, 4],
      [7, 0],
      [9, 4],
      [10, 0],
      [12, 3],
    ]);
    expect(posed.prompt).toContain('Q₃(0.5)');
    expect(posed.prompt).toContain('Segment Q₃ blends P₀ … P₃');
    // B(½) = (1/48)(1, 23, 23, 1): x = (0 + 23·3 + 23·4 + 7)/48 = 168/48 = 3.5,
    // y = (4 + 23·1 + 23·4 + 0)/48 = 119/48.
    expect(task.answer[0]).toBeCloseTo(3.5, 12);
    expect(task.answer[1]).toBeCloseTo(119 / 48, 12);
  });

  it('takes a guess within 0.3 and refuses one 0.4 off, saying where the point is', () => {
    expect(task.check([3.6, 2.6]).correct).toBe(true);
    const wrong = task.check([3.5, 119 / 48 + 0.4]);
    expect(wrong.correct).toBe(false);
    expect(wrong.message).toContain('(3.5, 2.479)');
    expect(wrong.message).toContain('Segment Q₃');
  });

  it('opens on the polygon with the cursor elsewhere; Show me walks to the segment at s = 0.5', () => {
    const opened = derive(posed.state);
    expect(opened.shown.name).toBe('polygon');
    expect(gap(opened.point, task.answer)).toBeGreaterThan(1);
    const working = derive({ ...posed.working, step: 2 });
    expect(working.shown.name).toBe('segment');
    expect(gap(working.point, task.answer)).toBeLessThan(1e-12);
  });
});

describe('An entry of the Cox–de Boor triangle (seed 42)', () => {
  const posed = byId('cox-de-boor').pose(42, defaults);
  const task = taskOf(posed, 'number');

  it('poses N(5,2) at u = 8.5 on uneven knots; worked row by row it is 0.59375', () => {
    expect(posed.prompt).toContain('u0 … u9 = 0, 1, 2, 4, 6, 7, 8, 10, 12, 14');
    expect(posed.prompt).toContain('N(5,2) at u = 8.5');
    // u = 8.5 lies in [u6, u7) = [8, 10): row 0 is N(6,0) = 1.
    // Row 1: N(5,1) = (u7 − u)/(u7 − u6) = 1.5/2 = 0.75, N(6,1) = (u − u6)/(u7 − u6) = 0.5/2 = 0.25.
    // Row 2: N(5,2) = (u − u5)/(u7 − u5)·N(5,1) + (u8 − u)/(u8 − u6)·N(6,1)
    //              = (1.5/3)·0.75 + (3.5/4)·0.25 = 0.375 + 0.21875 = 0.59375.
    expect(task.answer[0]).toBeCloseTo(0.59375, 12);
    expect(task.check([0.594]).correct).toBe(true);
    expect(task.check([0.6]).correct).toBe(false);
  });

  it('names the step of each slip', () => {
    // Factors swapped: (3.5/4)·0.75 + (1.5/3)·0.25 = 0.65625 + 0.125 = 0.78125.
    expect(task.check([0.781]).message).toContain('factors swapped');
    // One-knot spans: (1.5/1)·0.75 + (3.5/2)·0.25 = 1.125 + 0.4375 = 1.5625.
    expect(task.check([1.5625]).message).toContain('two knots wide');
    // The uniform middle piece at t = (8.5 − 8)/2 = 0.25: (−2t² + 2t + 1)/2 = 0.6875.
    expect(task.check([0.6875]).message).toContain('uniform piece');
    expect(task.check([0.75]).message).toContain('row 1');
    // N(4,2)(8.5) = (1.5/3)·N(5,1) = 0.375 (N(4,1) is 0 there): the neighbour.
    expect(task.check([0.375]).message).toContain('N(4,2), the neighbour');
    expect(task.check([0.2]).message).toContain('row by row');
  });

  it('opens on the knots with no row of the triangle; Show me reaches row 2 at u = 8.5', () => {
    const opened = derive(posed.state);
    expect(opened.shown.name).toBe('knots');
    expect(shownIn(posed.state).has('row')).toBe(false);
    const last = lastStep(posed.working);
    const rows = derive({ ...posed.working, step: last - 1 });
    expect(shownIn(rows.state).count('row')).toBe(3);
    expect(rows.u).toBeCloseTo(8.5, 12);
    expect(rows.table[2][5]).toBeCloseTo(0.59375, 12);
  });
});

describe('Knots that make the curve touch a point (seed 1)', () => {
  const posed = byId('through-point').pose(1, defaults);
  const task = taskOf(posed, 'construct');

  it('asks for P₃ on uniform knots 0 … 10, where the curve stays 0.95 away', () => {
    expect(posed.prompt).toContain('through P₃ (within 0.15)');
    expect(posed.state.knots).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10]);
    // Near P₃ = (6, 1) the curve is at its joint P(5) = (P₂ + 4P₃ + P₄)/6 = ((4, 5) + (24, 4) + (8, 3))/6 = (6, 2).
    const verdict = task.check(posed.state);
    expect(verdict.correct).toBe(false);
    expect(verdict.message).toContain('within 0.95 of P₃');
  });

  it('stacking u4, u5, u6 at 5 makes P(5) = P₃: at u = 5 only N(3,3) is 1', () => {
    // At u = 5 (span [u6, u7) = [5, 7)): N(5,1) = (7 − 5)/(7 − 5) = 1, N(4,2) = (7 − 5)/(7 − 5)·1 = 1,
    // N(3,3) = (u7 − u)/(u7 − u4)·N(4,2) = 2/2 = 1.
    expect(task.solution.knots).toEqual([0, 1, 2, 3, 5, 5, 5, 7, 8, 9, 10]);
    expect(task.check(task.solution)).toEqual({
      correct: true,
      message: 'Correct: the curve passes through P₃, at u = 5.',
    });
  });

  it('is solved by two drags on the knot strip (u4 onto u5, then u6 onto it)', () => {
    let state = posed.state;
    for (const [id, to] of [
      ['u4', 4.97],
      ['u6', 5.04],
    ] as const)
      state = knotFigure.moveHandle!(state, id, [to, 0], derive(state));
    expect(state.knots).toEqual(task.solution.knots);
    expect(task.check(state).correct).toBe(true);
  });

  it('a double knot is not enough: C¹ there, and the curve misses P₃', () => {
    const double = { ...posed.state, knots: [0, 1, 2, 3, 4.5, 4.5, 6, 7, 8, 9, 10] };
    expect(task.check(double).correct).toBe(false);
  });
});

describe('every seed', () => {
  const pose = (id: string, seed: number) => byId(id).pose(seed, defaults);

  it('has three exercises, one of each kind', () => {
    expect(exercises.map((e) => e.kind).sort()).toEqual(['construct', 'number', 'point']);
  });

  it('passes the kit’s checks, the segment’s point inside the polygon’s box', () => {
    const inBox = (state: BSplineState, [x, y]: Point) => {
      const box = boundsOf(state.points);
      return x >= box.minX && x <= box.maxX && y >= box.minY && y <= box.maxY;
    };
    checkExercises(exercises, defaults, { runs: 200, inFigure: inBox });
  });

  it('states the tolerance in the prompt, in states the link can hold, with a working to walk', () => {
    for (const { id } of exercises)
      fc.assert(
        fc.property(seeds, (seed) => {
          const posed = pose(id, seed);
          const tolerance = posed.task.kind === 'construct' ? 0.15 : posed.task.tolerance;
          expect(posed.prompt).toContain(`within ${tolerance}`);
          // States as the link would open them: normalize has nothing to fix.
          expect(normalize(posed.state).issues).toEqual([]);
          expect(normalize(posed.working).state).toEqual(posed.working);
          expect(lastStep(posed.working)).toBeGreaterThan(1);
        }),
        { numRuns: 60 },
      );
  });

  it('segment point: hidden at first, reached by Show me', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('segment-point', seed);
        const task = taskOf(posed, 'point');
        // The figure draws no curve at its step, and the panel's P(s) is not the answer.
        const opened = derive(posed.state);
        expect(shownIn(posed.state).has('segment')).toBe(false);
        expect(gap(opened.point, task.answer)).toBeGreaterThan(task.tolerance);
        expect(gap(derive({ ...posed.working, step: 2 }).point, task.answer)).toBeLessThan(1e-9);
      }),
      { numRuns: 200 },
    );
  });

  it('Cox–de Boor: an answer in (0, 1], on uneven knots, no row shown at first', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('cox-de-boor', seed);
        const task = taskOf(posed, 'number');
        const [answer] = task.answer;
        expect(answer).toBeGreaterThan(0);
        expect(answer).toBeLessThanOrEqual(1);
        expect(shownIn(posed.state).has('row')).toBe(false);
        // "Show me" at its last row has the entry in its triangle.
        const row = derive({ ...posed.working, step: lastStep(posed.working) - 1 });
        expect(row.table[2]).toContainEqual(expect.closeTo(answer, 12));
        const gaps = posed.state.knots.slice(1).map((u, j) => u - posed.state.knots[j]);
        expect(new Set(gaps).size).toBeGreaterThan(1);
      }),
      { numRuns: 200 },
    );
  });

  it('agrees with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});
