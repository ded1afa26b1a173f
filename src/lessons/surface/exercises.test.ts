import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/surface';
import { defaultsOf } from '../../app/urlState';
import type { Posed, Task } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import { exercises } from './exercises';
import { patchShown } from './figure';
import lesson from './lesson';
import type { SurfaceModel } from './model';
import { secondNetPoints } from './points';
import { type SurfaceState, schema } from './state';

// Each exercise for one seed worked by hand, then every seed: solvable, the
// posed figure not yet showing the answer, "Show me" reaching it.

const defaults = defaultsOf(schema);
const derive = (s: SurfaceState) => lesson.derive(s) as SurfaceModel;
const lastStep = (s: SurfaceState) => lesson.steps!.count(s);
const byId = (id: string) => exercises.find((e) => e.id === id)!;
const gap = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);

function taskOf<K extends Task<SurfaceState>['kind']>(posed: Posed<SurfaceState>, kind: K) {
  if (posed.task.kind !== kind) throw new Error(`a ${posed.task.kind} task, not ${kind}`);
  return posed.task as Extract<Task<SurfaceState>, { kind: K }>;
}

describe('Where is a point of the patch? (seed 1)', () => {
  const posed = byId('patch-point').pose(1, defaults);
  const task = taskOf(posed, 'point');

  it('P(0.75, 0.5) of a flat net: the rows at v = ½, then their curve at u = ¾', () => {
    expect(posed.prompt).toContain('P(0.75, 0.5)');
    expect(posed.state.net.map((row) => row.map(([x, y, z]) => [x, y, z]))).toEqual([
      [
        [0, -1, 0],
        [0, 4, 0],
        [1, 5, 0],
        [0, 10, 0],
      ],
      [
        [3, 1, 0],
        [3, 3, 0],
        [2, 6, 0],
        [2, 8, 0],
      ],
      [
        [6, -1, 0],
        [6, 4, 0],
        [5, 5, 0],
        [5, 9, 0],
      ],
      [
        [9, 1, 0],
        [8, 2, 0],
        [9, 6, 0],
        [10, 8, 0],
      ],
    ]);
    // f(½) = (1, 3, 3, 1)/8 along each row: r0 = (3, 36)/8, r1 = (20, 36)/8, r2 = (44, 35)/8, r3 = (70, 33)/8.
    // f(¾) = (1, 9, 27, 27)/64: x = (3 + 9·20 + 27·44 + 27·70)/512 = 3261/512 = 6.369140625,
    // y = (36 + 9·36 + 27·35 + 27·33)/512 = 2196/512 = 4.2890625.
    expect(task.answer[0]).toBeCloseTo(3261 / 512, 12);
    expect(task.answer[1]).toBeCloseTo(2196 / 512, 12);
  });

  it('takes a guess within 0.3, refuses one 0.4 off and names the rows construction', () => {
    expect(task.check([6.5, 4.5]).correct).toBe(true);
    const wrong = task.check([6.369, 4.689]);
    expect(wrong.correct).toBe(false);
    expect(wrong.message).toContain('(6.369, 4.289)');
    expect(wrong.message).toContain('Choose v, then u');
  });

  it('opens on the net with no point; Show me (choose v, then u) reaches it', () => {
    const opened = derive(posed.state);
    expect(patchShown(opened).point).toBe(false);
    expect(gap(opened.point, task.answer)).toBeGreaterThan(1);
    const shown = derive({ ...posed.working, step: 4 });
    expect(shown.shown.name).toBe('point');
    expect(gap(shown.point, task.answer)).toBeLessThan(1e-12);
  });
});

describe('Compute a height z(u, v) (seed 1)', () => {
  const posed = byId('patch-height').pose(1, defaults);
  const task = taskOf(posed, 'number');

  it('z(0.75, 0.4) of the inner heights 2, 1, 2, 3 is 0.891', () => {
    expect(posed.prompt).toContain('P₁,₁ at z = 2, P₁,₂ at z = 1, P₂,₁ at z = 2, P₂,₂ at z = 3');
    expect(posed.prompt).toContain('z(0.75, 0.4)');
    // f₁(¾) = 9/64, f₂(¾) = 27/64; f₁(0.4) = 3·0.4·0.6² = 0.432, f₂(0.4) = 3·0.4²·0.6 = 0.288.
    // z = 9/64·(2·0.432 + 1·0.288) + 27/64·(2·0.432 + 3·0.288) = 0.162 + 0.729 = 0.891.
    expect(task.answer[0]).toBeCloseTo(0.891, 12);
    expect(task.check([0.891]).correct).toBe(true);
    expect(task.check([0.895]).correct).toBe(false);
  });

  it('names the step of each slip', () => {
    // u and v swapped: 0.432·(2·9/64 + 1·27/64) + 0.288·(2·9/64 + 3·27/64) = 0.30375 + 0.4455 = 0.74925.
    expect(task.check([0.749]).message).toContain('u and v are swapped');
    // Without the binomial 3s every inner weight is 9 times smaller: 0.891/9 = 0.099.
    expect(task.check([0.099]).message).toContain('binomial 3');
    // t and 1 − t swapped: z(0.25, 0.6) = 27/64·(2·0.288 + 0.432) + 9/64·(2·0.288 + 3·0.432) = 0.6885.
    expect(task.check([0.6885]).message).toContain('1 − t are swapped');
    expect(task.check([1]).message).toContain('matrix form step by step');
  });

  it('opens on B with the panel at the corner; Show me ends on the product, 0.891', () => {
    const opened = derive(posed.state);
    expect(opened.shown.name).toBe('coordinates');
    expect(opened.matrix.value).toBe(0);
    const product = derive({ ...posed.working, step: lastStep(posed.working) });
    expect(product.shown.name).toBe('product');
    expect(product.matrix.value).toBeCloseTo(0.891, 12);
  });
});

describe('Join two patches C¹ (seed 1)', () => {
  const posed = byId('smooth-join').pose(1, defaults);
  const task = taskOf(posed, 'construct');

  it('has Q₁,₃ half a unit off (4, 2.5, 0) where C¹ needs 2P₃,₃ − P₂,₃ = (4, 3, 0)', () => {
    expect(posed.state.secondNet[1][3]).toEqual([4, 2.5, 0]);
    expect(posed.state.net[2][3]).toEqual([2, 3, 0]);
    expect(posed.state.net[3][3]).toEqual([3, 3, 0]);
    const verdict = task.check(posed.state);
    expect(verdict.correct).toBe(false);
    expect(verdict.message).toContain('one column is off');
    expect(verdict.message).toContain('At n = 3');
    expect(verdict.message).toContain('by 0.5');
    expect(verdict.message).toContain('Q₁,₃ belongs at 2P₃,₃ − P₂,₃');
  });

  it('is solved by moving that one point in x and y, its height kept', () => {
    const moved = secondNetPoints.move(posed.state, 3, [4, 3, 0]);
    expect(moved.secondNet[1][3]).toEqual([4, 3, 0]);
    expect(task.check(moved).correct).toBe(true);
    expect(task.check(secondNetPoints.move(posed.state, 3, [4.05, 3.05, 0])).correct).toBe(true);
    expect(task.check(secondNetPoints.move(posed.state, 3, [4, 3.2, 0])).correct).toBe(false);
  });

  it('a torn edge is not a join: P₃,₁ lifted off Q₀,₁', () => {
    const net = posed.state.net.map((row, m) =>
      row.map((p, n) => (m === 3 && n === 1 ? [p[0], p[1], p[2] + 1] : p)),
    );
    const verdict = task.check({ ...task.solution, net });
    expect(verdict.correct).toBe(false);
    expect(verdict.message).toContain('torn at column n = 1');
    expect(verdict.message).toContain('where P₃,₁ and Q₀,₁ are');
  });
});

describe('every seed', () => {
  const pose = (id: string, seed: number) => byId(id).pose(seed, defaults);

  it('has three exercises, one of each kind', () => {
    expect(exercises.map((e) => e.kind).sort()).toEqual(['construct', 'number', 'point']);
  });

  it('passes the kit’s checks, the patch’s point strictly inside the net’s box', () => {
    const insideNet = (state: SurfaceState, [x, y]: Point) => {
      const box = boundsOf(state.net.flat());
      return x > box.minX && x < box.maxX && y > box.minY && y < box.maxY;
    };
    checkExercises(exercises, defaults, { runs: 200, inFigure: insideNet });
  });

  it('states the tolerance in the prompt, with a working to walk', () => {
    for (const { id } of exercises)
      fc.assert(
        fc.property(seeds, (seed) => {
          const posed = pose(id, seed);
          const tolerance = posed.task.kind === 'construct' ? 0.1 : posed.task.tolerance;
          expect(posed.prompt).toContain(`within ${tolerance}`);
          expect(lastStep(posed.working)).toBeGreaterThan(1);
        }),
        { numRuns: 60 },
      );
  });

  it('patch point: a flat net, the point hidden at first, reached by Show me', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('patch-point', seed);
        const task = taskOf(posed, 'point');
        expect(posed.state.net.flat().every((p) => p[2] === 0)).toBe(true);
        const opened = derive(posed.state);
        expect(patchShown(opened).point).toBe(false);
        expect(gap(opened.point, task.answer)).toBeGreaterThan(task.tolerance);
        expect(gap(derive({ ...posed.working, step: 4 }).point, task.answer)).toBeLessThan(1e-9);
      }),
      { numRuns: 100 },
    );
  });

  it('patch height: an answer inside the heights’ range, not the panel’s', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('patch-height', seed);
        const task = taskOf(posed, 'number');
        const [z] = task.answer;
        expect(z).toBeGreaterThan(0);
        expect(z).toBeLessThan(3);
        // 3× the tolerance below (the kit checks above).
        expect(task.check([z - 3 * task.tolerance]).correct).toBe(false);
        expect(Math.abs(derive(posed.state).matrix.value - z)).toBeGreaterThan(task.tolerance);
        const product = derive({ ...posed.working, step: lastStep(posed.working) });
        expect(product.matrix.value).toBeCloseTo(z, 12);
      }),
      { numRuns: 100 },
    );
  });

  it('smooth join: only Q’s row 1 moves, in x and y', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('smooth-join', seed);
        const task = taskOf(posed, 'construct');
        expect(task.solution.net).toEqual(posed.state.net);
        posed.state.secondNet.forEach((row, m) =>
          row.forEach((p, n) => {
            const target = task.solution.secondNet[m][n];
            if (m !== 1) expect(p).toEqual(target);
            expect(p[2]).toBe(target[2]);
          }),
        );
      }),
      { numRuns: 200 },
    );
  });

  it('agrees with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});
