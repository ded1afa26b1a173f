import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import type { Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import {
  ARRIVAL_TOLERANCE,
  MIDPOINT_TOLERANCE,
  SWEEP_TOLERANCE,
  arrivalGradient,
  exercises,
} from './exercises';
import data from '../../../tests/e2e/practice/road';
import lesson from './lesson';
import type { RoadModel } from './model';
import { type RoadState, normalize, schema } from './state';

const defaults = defaultsOf(schema);
const derive = (s: RoadState) => lesson.derive(s) as RoadModel;
const lastStep = (s: RoadState) => lesson.steps!.count(s);
const map = lesson.figures.find((f) => f.id === 'map')!;
const pose = (id: string, seed: number) => exercises.find((e) => e.id === id)!.pose(seed, defaults);
const gap = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);

function task<K extends 'point' | 'number' | 'construct'>(posed: Posed<RoadState>, kind: K) {
  if (posed.task.kind !== kind) throw new Error(`a ${kind} task, not ${posed.task.kind}`);
  return posed.task as Extract<Posed<RoadState>['task'], { kind: K }>;
}

describe('the road’s exercises', () => {
  it('are three, one of each kind, with their own ids', () => {
    expect(exercises.map((e) => e.kind).sort()).toEqual(['construct', 'number', 'point']);
    expect(new Set(exercises.map((e) => e.id)).size).toBe(exercises.length);
    expect(lesson.exercises).toBe(exercises);
  });

  it('pass the kit’s checks, the point to guess strictly inside the map', () => {
    const onMap = (state: RoadState, [x, y]: Point) => {
      const box = map.bounds(derive(state));
      return x > box.minX && x < box.maxX && y > box.minY && y < box.maxY;
    };
    checkExercises(exercises, defaults, { inFigure: onMap });
  });

  it('pose states the link can hold', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        for (const e of exercises) {
          const posed = e.pose(seed, defaults);
          for (const s of [posed.state, posed.working]) {
            expect(normalize(s).state).toEqual(s);
            expect(s.step).toBeLessThanOrEqual(lastStep(s));
          }
          expect(posed.working.step).toBe(0);
        }
      }),
      { numRuns: 60 },
    );
  });
});

describe('Where is the Hermite road at p̄ = i + ½?', () => {
  // Seed 1: P₀ (0, 40), P₁ (26, 48), P₂ (42, 4), P₃ (58, 12), P₄ (80, 48), p̄ = 2.5 (segment 2).
  // D₂ = (P₃ − P₁)/2 = (16, −18), D₃ = (P₄ − P₂)/2 = (19, 22);
  // P(½) = ½(P₂ + P₃) + ⅛(D₂ − D₃) = (50, 8) + ⅛(−3, −40) = (49.625, 3).
  const posed = pose('hermite-midpoint', 1);
  const point = task(posed, 'point');

  it('poses the villages and p̄ in the prompt, and the point by hand', () => {
    expect(posed.state.villages).toEqual([
      [0, 40],
      [26, 48],
      [42, 4],
      [58, 12],
      [80, 48],
    ]);
    expect(posed.prompt).toContain('P₂ (42, 4)');
    expect(posed.prompt).toContain('p̄ = 2.5');
    expect(point.answer[0]).toBeCloseTo(49.625, 12);
    expect(point.answer[1]).toBeCloseTo(3, 12);
  });

  it('accepts the point, rejects one 3 km off, and names the slip of the chord’s middle', () => {
    expect(point.check([49.6, 3.1]).correct).toBe(true);
    expect(point.check([52.625, 3]).correct).toBe(false);
    const middle = point.check([50, 8]);
    expect(middle.correct).toBe(false);
    expect(middle.message).toContain('middle of the straight line P₂P₃');
    // D without the ½: the bend twice, (50, 8) + 2·(−0.375, −5) = (49.25, −2).
    expect(point.check([49.25, -2]).message).toContain('half the chord');
    // Segment 1 at p = ½ instead of segment 2.
    const one = derive({ ...posed.working, step: lastStep(posed.working), pBar: 1.5 });
    expect(point.check(one.visible!.marker!.point).message).toContain('segment 1');
  });

  it('hides the road at the start and walks to the marker on the answer', () => {
    const start = derive(posed.state);
    expect(start.visible!.pieces).toEqual([]);
    expect(start.visible!.marker).toBeNull();
    const end = derive({ ...posed.working, step: lastStep(posed.working) });
    expect(gap(end.visible!.marker!.point, point.answer)).toBeLessThan(1e-12);
  });

  it('has its tolerance, and the chord’s middle never passes, for every seed', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const p = pose('hermite-midpoint', seed);
        const t = task(p, 'point');
        expect(t.tolerance).toBe(MIDPOINT_TOLERANCE);
        // The chord's middle is never close enough to pass.
        const [a, b] = [p.state.villages[p.state.pBar - 0.5], p.state.villages[p.state.pBar + 0.5]];
        expect(t.check([(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]).correct).toBe(false);
      }),
    );
  });
});

describe('The first rows of the forward sweep', () => {
  // Seed 1: x = 0, 14, 46, 56. Row 0 [2 1 | 3·14 = 42]: Γ₀ = 42/2 = 21.
  // Row 1 [1 4 1 | 3·46 = 138]: pivot 4 − ½ = 3.5, Γ₁ = (138 − 21)/3.5 = 117/3.5 = 33.428571…
  const posed = pose('thomas-sweep', 1);
  const numbers = task(posed, 'number');

  it('poses the x of the villages, and Γ₀, Γ₁ by hand', () => {
    expect(posed.state.villages.map((p) => p[0])).toEqual([0, 14, 46, 56]);
    expect(posed.prompt).toContain('x = 0, 14, 46, 56');
    expect(numbers.answer[0]).toBeCloseTo(21, 12);
    expect(numbers.answer[1]).toBeCloseTo(117 / 3.5, 12);
  });

  it('accepts two decimals, rejects a wrong Γ₁, and names each slip', () => {
    expect(numbers.check([21, 33.43]).correct).toBe(true);
    expect(numbers.check([21, 33.45]).correct).toBe(false);
    // Pivot 4: 117/4 = 29.25.
    expect(numbers.check([21, 29.25]).message).toContain('pivot is b₁ − a₁γ₀ = 4 − ½ = 3.5');
    // No factor 3: Γ₀ = 14/2 = 7, Γ₁ = (46 − 7)/3.5 = 11.142857…
    expect(numbers.check([7, 11.14]).message).toContain('the 3 comes from');
    // Γ₀ not subtracted: 138/3.5 = 39.428571…
    expect(numbers.check([21, 39.43]).message).toContain('Subtract a₁Γ₀');
    // Row 0 not divided by 2: Γ₀ = 42, γ₀ = 1, Γ₁ = (138 − 42)/3 = 32.
    expect(numbers.check([42, 32]).message).toContain('divide it by its pivot 2');
    // The end row's right-hand side 3(x₂ − x₁) = 96: Γ₁ = (96 − 21)/3.5 = 21.428571…
    expect(numbers.check([21, 21.43]).message).toContain('an inner row');
    expect(numbers.check([20, 30]).message).toContain('Sweep row by row');
  });

  it('hides the sweep at the start; the working’s captions reach Γ₁', () => {
    expect(derive(posed.state).progress!.swept).toBe(0);
    const formulas = Array.from({ length: lastStep(posed.working) + 1 }, (_, k) => {
      const s = { ...posed.working, step: k };
      return lesson.steps!.formula!(derive(s), s) ?? '';
    });
    expect(formulas.some((f) => f.includes('33.4286'))).toBe(true);
  });

  it('is the sweep worked again for every seed, and no slip passes', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const p = pose('thomas-sweep', seed);
        const t = task(p, 'number');
        expect(t.tolerance).toBe(SWEEP_TOLERANCE);
        expect(t.check([t.answer[0], t.answer[1] + 3 * SWEEP_TOLERANCE]).correct).toBe(false);
        // Independently: Γ₀ = 3(x₁ − x₀)/2, Γ₁ = (3(x₂ − x₀) − Γ₀)/(4 − ½).
        const [x0, x1, x2] = p.state.villages.map((v) => v[0]);
        const gamma0 = (3 * (x1 - x0)) / 2;
        expect(t.answer[0]).toBeCloseTo(gamma0, 9);
        expect(t.answer[1]).toBeCloseTo((3 * (x2 - x0) - gamma0) / 3.5, 9);
        // The slips never pass, and each gets a hint of its own.
        const slips = [
          [gamma0, (3 * (x2 - x0) - gamma0) / 4],
          [gamma0, (3 * (x2 - x0)) / 3.5],
          [gamma0, (3 * (x2 - x1) - gamma0) / 3.5],
        ];
        const hints = slips.map((values) => t.check(values));
        hints.forEach((verdict) => expect(verdict.correct).toBe(false));
        expect(new Set(hints.map((verdict) => verdict.message)).size).toBe(slips.length);
      }),
    );
  });
});

describe('Choose B₀ so the quadratic road meets the road at P₃', () => {
  // Seed 1: P₀ (0, 6), P₁ (14, 22), P₂ (46, 40), P₃ (56, 34), asked D₃ = (−36, −24).
  // Back from the end: B₂ = P₃ − D₃/2 = (74, 46), B₁ = 2P₂ − B₂ = (18, 34), B₀ = 2P₁ − B₁ = (10, 10).
  // Posed: D₀ = (40, −4), B₀ = P₀ + D₀/2 = (20, 4): B₁ = (8, 40), B₂ = (84, 40), D₃ = 2(P₃ − B₂) = (−56, −12).
  const posed = pose('quadratic-arrival', 1);
  const construct = task(posed, 'construct');
  const moveB0 = (s: RoadState, to: Point) => map.moveHandle!(s, 'q', to, derive(s));

  it('poses the villages and the gradient asked for, and opens away from it', () => {
    expect(posed.prompt).toContain('P₁ (14, 22)');
    expect(posed.prompt).toContain('D₃ = (−36, −24)');
    expect(posed.state.quadraticGradient).toEqual([40, -4]);
    expect(arrivalGradient(posed.state)).toEqual([-56, -12]);
    const verdict = construct.check(posed.state);
    expect(verdict.correct).toBe(false);
    expect(verdict.message).toContain('(−56, −12)');
  });

  it('passes once B₀’s handle is dragged to (10, 10), and fails 3 km away', () => {
    const handles = map.handles!(derive(posed.state)).map((h) => h.id);
    expect(handles).toContain('q');
    const solved = moveB0(posed.state, [10, 10]);
    expect(solved.quadraticGradient).toEqual([20, 8]);
    expect(construct.check(solved).correct).toBe(true);
    expect(construct.check(moveB0(posed.state, [13, 10])).correct).toBe(false);
  });

  it('wants the villages left alone', () => {
    const moved = {
      ...construct.solution,
      villages: construct.solution.villages.map((p) => [p[0], p[1] + 1]),
    };
    expect(construct.check(moved).message).toContain('Keep the villages');
  });

  it('is solvable by dragging B₀ to a place on the map, for every seed', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const p = pose('quadratic-arrival', seed);
        const t = task(p, 'construct');
        // Where the drag goes: B₀ of the solution, inside the map the posed state fits.
        const m = derive(t.solution);
        const box = map.bounds(derive(p.state));
        const b0 = m.quadraticControl;
        expect(b0[0]).toBeGreaterThanOrEqual(box.minX);
        expect(b0[0]).toBeLessThanOrEqual(box.maxX);
        expect(b0[1]).toBeGreaterThanOrEqual(box.minY);
        expect(b0[1]).toBeLessThanOrEqual(box.maxY);
        expect(t.check(moveB0(p.state, b0)).correct).toBe(true);
        // Within the tolerance: B₀ half a km off still passes (D₃ moves by twice that).
        expect(t.check(moveB0(p.state, [b0[0] + 0.5, b0[1]])).correct).toBe(true);
        expect(ARRIVAL_TOLERANCE).toBe(2);
      }),
    );
  });
});

describe('the browser test’s practice data', () => {
  it('matches each posed prompt, and its answers pass where its wrong answers fail', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});
