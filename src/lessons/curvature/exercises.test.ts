import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/curvature';
import { defaultsOf } from '../../app/urlState';
import type { Posed, Task } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import { exercises } from './exercises';
import lesson from './lesson';
import type { CurvatureModel } from './model';
import { planePoints } from './points';
import { type CurvatureState, schema } from './state';

// Each exercise for one seed worked by hand, then every seed: solvable, the
// posed figure not yet showing the answer, "Show me" reaching it.

const defaults = defaultsOf(schema);
const derive = (s: CurvatureState) => lesson.derive(s) as CurvatureModel;
const at = (s: CurvatureState) => derive(s).plane!.at;
const lastStep = (s: CurvatureState) => lesson.steps!.count(s);
const byId = (id: string) => exercises.find((e) => e.id === id)!;
const gap = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);
/** The working at the step that shows κ and the osculating circle. */
const atCurvatureStep = (s: CurvatureState) => derive({ ...s, step: 4 });

function taskOf<K extends Task<CurvatureState>['kind']>(posed: Posed<CurvatureState>, kind: K) {
  if (posed.task.kind !== kind) throw new Error(`a ${posed.task.kind} task, not ${kind}`);
  return posed.task as Extract<Task<CurvatureState>, { kind: K }>;
}

// Seed 1 poses the arch P0 = (1, 2), P1 = (1, 5), P2 = (4, 5), P3 = (5, 2) at t = 0.5 in both
// the point and the number exercise. By hand: P′(½) = ¾(P3 + P2 − P1 − P0) = ¾(7, 0) = (5.25, 0),
// P″(½) = 3(P0 − P1 − P2 + P3) = 3(1, −6) = (3, −18), x′y″ − y′x″ = −94.5, |P′|³ = 5.25³ = 144.703125,
// κ = −94.5/144.703125 = −32/49 ≈ −0.653 (turning right), R = 49/32 = 1.53125.
const ARCH = [
  [1, 2],
  [1, 5],
  [4, 5],
  [5, 2],
];

describe('Where is the centre of curvature? (seed 1)', () => {
  const posed = byId('circle-centre').pose(1, defaults);
  const task = taskOf(posed, 'point');

  it('is P(½) + R·N = (2.625, 4.25) + 1.53125·(0, −1) = (2.625, 2.71875)', () => {
    expect(posed.state.points).toEqual(ARCH);
    expect(posed.prompt).toContain('P(0.5)');
    // P(½) = (P0 + 3P1 + 3P2 + P3)/8 = (21, 34)/8; T = (1, 0), turning right: N = (0, −1).
    expect(task.answer[0]).toBeCloseTo(2.625, 12);
    expect(task.answer[1]).toBeCloseTo(4.25 - 49 / 32, 12);
  });

  it('takes a guess within 0.2, refuses one 0.3 off and points to the normal and κ', () => {
    expect(task.check([2.7, 2.6]).correct).toBe(true);
    const wrong = task.check([2.625, 3.02]);
    expect(wrong.correct).toBe(false);
    expect(wrong.message).toContain('(2.625, 2.719)');
    expect(wrong.message).toContain('P(t) + N/|κ|');
  });

  it('opens on the curve alone at t = 1; Show me draws the circle at t = 0.5', () => {
    // Its circle at t = 0 is centred at (5.5, 2), 2.96 from the answer; at t = 1 at (0, 0.333), 3.55 away.
    expect(posed.state.t).toBe(1);
    const opened = derive(posed.state);
    expect(opened.shown.name).toBe('curve');
    expect(gap(opened.plane!.at.circle!.centre, task.answer)).toBeGreaterThan(task.tolerance);
    const shown = atCurvatureStep(posed.working);
    expect(shown.shown.has('curvature')).toBe(true);
    expect(gap(shown.plane!.at.circle!.centre, task.answer)).toBeLessThan(1e-12);
  });
});

describe('Compute the curvature κ', () => {
  it('seed 1: κ(0.5) = −32/49, with a hint for each slip', () => {
    const posed = byId('curvature-value').pose(1, defaults);
    const task = taskOf(posed, 'number');
    expect(posed.prompt).toContain('P₀ = (1, 2), P₁ = (1, 5), P₂ = (4, 5), P₃ = (5, 2)');
    expect(posed.prompt).toContain('at t = 0.5');
    expect(task.answer[0]).toBeCloseTo(-32 / 49, 12);
    expect(task.check([-0.653]).correct).toBe(true);
    expect(task.check([-0.66]).correct).toBe(false);
    // Without the 3 and the 6: (7/4, 0) × (1/2, −3) over (7/4)³ = −5.25/5.359375 = −0.980 = 1.5κ.
    expect(task.check([-0.98]).message).toContain('factor 3');
    // Over |P′|² instead of |P′|³: −94.5/27.5625 = −3.429.
    expect(task.check([-3.429]).message).toContain('cube of the speed');
    expect(task.check([0.653]).message).toContain('The sign');
    expect(task.check([1.531]).message).toContain('radius R');
    expect(task.check([-0.5]).message).toContain('the velocity P′(0.5)');
  });

  it('seed 2: κ(1) = (2/3)·15/17^{3/2} at the end, and κ(0) is t and 1 − t swapped', () => {
    const posed = byId('curvature-value').pose(2, defaults);
    const task = taskOf(posed, 'number');
    expect(posed.prompt).toContain('P₀ = (1, 1), P₁ = (1, −4), P₂ = (5, −3), P₃ = (6, 1)');
    expect(posed.prompt).toContain('at t = 1');
    // P′(1) = 3(P3 − P2) = (3, 12), P″(1) = 6(P3 − 2P2 + P1) = 6(−3, 3) = (−18, 18):
    // x′y″ − y′x″ = 54 + 216 = 270, |P′|³ = 153^{3/2}; κ = 270/153^{3/2} = (2/3)·15/17^{3/2} ≈ 0.1427.
    const kappa = 270 / 153 ** 1.5;
    expect(task.answer[0]).toBeCloseTo(kappa, 12);
    expect(task.check([0.143]).correct).toBe(true);
    // κ(0) = (2/3)·((0, −5) × (4, 1))/5³ = (2/3)·20/125 = 0.10667.
    expect(task.check([0.107]).message).toContain('t and 1 − t are swapped');
  });
});

describe('Make κ continuous at a join (seed 1)', () => {
  const posed = byId('smooth-join').pose(1, defaults);
  const task = taskOf(posed, 'construct');

  it('poses two pieces meeting at P₃ = (6, 3) with κ = 1/3 before and 1/2 after', () => {
    expect(posed.state.points).toEqual([
      [0, 4],
      [3, 5],
      [4, 3],
      [6, 3],
      [8, 3],
      [10, 6],
      [12, 5],
    ]);
    // Before: (2/3)·((P2 − P1) × (P3 − P2))/|P3 − P2|³ = (2/3)·((1, −2) × (2, 0))/8 = (2/3)·4/8 = 1/3.
    // After: (2/3)·((P4 − P3) × (P5 − P4))/8 = (2/3)·((2, 0) × (2, 3))/8 = (2/3)·6/8 = 1/2.
    const verdict = task.check(posed.state);
    expect(verdict.correct).toBe(false);
    expect(verdict.message).toContain('κ is 0.333 just before P₃ and 0.5 just after');
  });

  it('is solved by dragging P₅ to (10, 5), as far above the line y = 3 as P₁', () => {
    const moved = planePoints.move(posed.state, 5, [10, 5]);
    expect(task.check(moved).correct).toBe(true);
    expect(task.check(task.solution).correct).toBe(true);
    // (10, 5.1) is 0.1 too high: κ after = (2/3)·2·2.1/8 = 0.35, 0.0167 off: still within 0.03.
    expect(task.check(planePoints.move(posed.state, 5, [10, 5.1])).correct).toBe(true);
    expect(task.check(planePoints.move(posed.state, 5, [10, 5.3])).correct).toBe(false);
  });

  it('a corner at P₃ is not a smooth join, whatever κ does', () => {
    const corner = planePoints.move(posed.state, 4, [8, 3.5]);
    const verdict = task.check(corner);
    expect(verdict.correct).toBe(false);
    expect(verdict.message).toContain('a corner');
  });
});

describe('every seed', () => {
  const pose = (id: string, seed: number) => byId(id).pose(seed, defaults);

  it('has three exercises, one of each kind', () => {
    expect(exercises.map((e) => e.kind).sort()).toEqual(['construct', 'number', 'point']);
  });

  it('passes the kit’s checks, the centre within the polygon’s box (a quarter of its height to spare)', () => {
    const nearPolygon = (state: CurvatureState, [x, y]: Point) => {
      const box = boundsOf(state.points);
      const margin = 0.25 * (box.maxY - box.minY);
      return x >= box.minX && x <= box.maxX && y >= box.minY - margin && y <= box.maxY + margin;
    };
    checkExercises(exercises, defaults, { runs: 200, inFigure: nearPolygon });
  });

  it('states the tolerance in the prompt, in states the link can hold, with a working to walk', () => {
    for (const { id } of exercises)
      fc.assert(
        fc.property(seeds, (seed) => {
          const posed = pose(id, seed);
          const tolerance = posed.task.kind === 'construct' ? 0.03 : posed.task.tolerance;
          expect(posed.prompt).toContain(`within ${tolerance}`);
          expect(lesson.normalize!(posed.state).issues).toEqual([]);
          expect(lastStep(posed.working)).toBeGreaterThan(1);
        }),
        { numRuns: 60 },
      );
  });

  it('circle centre: hidden at first, reached by Show me', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('circle-centre', seed);
        const task = taskOf(posed, 'point');
        expect(derive(posed.state).shown.has('curvature')).toBe(false);
        expect(gap(at(posed.state).circle!.centre, task.answer)).toBeGreaterThan(task.tolerance);
        const shown = atCurvatureStep(posed.working).plane!.at.circle!;
        expect(gap(shown.centre, task.answer)).toBeLessThan(1e-9);
      }),
      { numRuns: 80 },
    );
  });

  it('κ: a non-zero answer; the panel’s κ at the posed cursor is another', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('curvature-value', seed);
        const task = taskOf(posed, 'number');
        const [kappa] = task.answer;
        expect(kappa !== 0).toBe(true);
        expect(derive(posed.state).shown.has('curvature')).toBe(false);
        expect(Math.abs(at(posed.state).curvature! - kappa)).toBeGreaterThan(task.tolerance);
        expect(atCurvatureStep(posed.working).plane!.at.curvature).toBeCloseTo(kappa, 12);
      }),
      { numRuns: 80 },
    );
  });

  it('smooth join: the solution moves only P₅', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('smooth-join', seed);
        const task = taskOf(posed, 'construct');
        const changed = posed.state.points.flatMap((p, i) =>
          gap(p, task.solution.points[i]) > 0 ? [i] : [],
        );
        expect(changed).toEqual([5]);
      }),
      { numRuns: 200 },
    );
  });

  it('agrees with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});
