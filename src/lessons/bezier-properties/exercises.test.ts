import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import data from '../../../tests/e2e/practice/bezier-properties';
import { defaultsOf } from '../../app/urlState';
import type { ConstructTask, NumberTask, PointTask, Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import { exercises } from './exercises';
import lesson from './lesson';
import type { ModelOf, PropertiesModel } from './model';
import { type ExperimentId, type PropertiesState, normalize, schema } from './state';

const defaults = defaultsOf(schema);
const modelOf = <X extends ExperimentId>(kind: X, s: PropertiesState): ModelOf<X> => {
  const m = lesson.derive(s) as PropertiesModel;
  if (m.kind !== kind) throw new Error(`a ${m.kind} model, not ${kind}`);
  return m as ModelOf<X>;
};
const pose = (id: string, seed: number): Posed<PropertiesState> =>
  exercises.find((e) => e.id === id)!.pose(seed, defaults);
const numberTask = (posed: Posed<PropertiesState>) => posed.task as NumberTask;
const pointTask = (posed: Posed<PropertiesState>) => posed.task as PointTask;
const constructTask = (posed: Posed<PropertiesState>) =>
  posed.task as ConstructTask<PropertiesState>;
const SUBSCRIPTS = '₀₁₂₃₄₅₆₇₈₉';
const factorial = (k: number): number => (k <= 1 ? 1 : k * factorial(k - 1));
/** C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ, written out again so the tests do not lean on src/math. */
const weightOf = (n: number, i: number, t: number) =>
  (factorial(n) / (factorial(i) * factorial(n - i))) * t ** i * (1 - t) ** (n - i);
/** The lesson opens a posed state as it is: nothing for `normalize` to put right. */
const settled = (s: PropertiesState) => expect(normalize(s).issues).toEqual([]);

describe('the Bézier properties exercises', () => {
  it('are the lesson’s, and pass the kit’s checks, the closed curve’s point inside the points’ box', () => {
    expect(lesson.exercises).toBe(exercises);
    const inBox = (state: PropertiesState, [x, y]: Point) => {
      const box = boundsOf(state.points);
      return x >= box.minX && x <= box.maxX && y >= box.minY && y <= box.maxY;
    };
    checkExercises(exercises, defaults, { runs: 300, inFigure: inBox });
  });

  it('agree with the browser test’s practice data, dragging the handles it names', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});

describe('how far does the curve move? (no local control)', () => {
  it('seed 1: P₁ of a degree-5 curve down by 2 moves it at most W(5, 1, 1/5)·2 = 0.8192', () => {
    const posed = pose('local-move', 1);
    expect(posed.prompt).toBe(
      'If P₁ of this curve of degree 5 moves down by 2, how far does the curve move at most (to 2 decimals)?',
    );
    // W(5, 1, t) = 5t(1 − t)⁴ is largest at t = 1/5: 5·(1/5)·(4/5)⁴ = 0.4096; times 2 = 0.8192.
    const task = numberTask(posed);
    expect(task.answer[0]).toBeCloseTo(0.8192, 14);
    expect(task.check([0.82]).correct).toBe(true);
    expect(task.check([0.9]).correct).toBe(false);
    expect(task.check([2]).message).toContain('a share of it');
    expect(task.check([0.41]).message).toContain('multiply it by the move, 2');
    // At t = ½: 5·(1/2)⁵·2 = 0.3125.
    expect(task.check([0.31]).message).toContain('not at t = ½');
    // Without C(5, 1) = 5: 0.08192·2 = 0.164.
    expect(task.check([0.16]).message).toContain('C(5, 1) = 5 is missing');
    // Six points taken as the degree: 6·(1/6)·(5/6)⁵·2 = 0.8038.
    expect(task.check([0.8]).message).toContain('N is the degree, 5');
  });

  it('opens on the curve as it is (nothing moved yet); the working moves P₁ and marks the largest move', () => {
    const posed = pose('local-move', 1);
    settled(posed.state);
    settled(posed.working);
    const before = modelOf('local', posed.state);
    expect(before.moved).toEqual([]);
    expect(before.shown.has('largest')).toBe(false);
    const after = modelOf('local', posed.working);
    expect(after.shown.last).toBe(true);
    expect(after.single?.index).toBe(1);
    expect(after.single!.peak * after.single!.shift).toBeCloseTo(0.8192, 14);
  });

  it('every seed: the answer is W(N, i, i/N) times the move, worked out again', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('local-move', seed);
        const task = numberTask(posed);
        const match = /P(.) of this curve of degree (\d) moves (up|down) by (\d)/.exec(
          posed.prompt,
        )!;
        const i = SUBSCRIPTS.indexOf(match[1]);
        const [n, shift] = [Number(match[2]), Number(match[4])];
        expect(posed.state.points).toHaveLength(n + 1);
        expect(posed.state.points).toEqual(posed.state.before);
        expect(task.answer[0]).toBeCloseTo(weightOf(n, i, i / n) * shift, 12);
        // The working moves exactly that point, by exactly that much.
        const moved = posed.working.points.flatMap((q, k) =>
          q[1] !== posed.state.points[k][1] ? [k] : [],
        );
        expect(moved).toEqual([i]);
        expect(Math.abs(posed.working.points[i][1] - posed.state.points[i][1])).toBe(shift);
        settled(posed.state);
      }),
      { numRuns: 300 },
    ));
});

describe('a point of the closed curve', () => {
  it('seed 7: (0, 0), (5, 3), (1, 3) closed by P₃ = P₀: P(0.5) = (2.25, 2.25)', () => {
    const posed = pose('closed-point', 7);
    expect(posed.state.points).toEqual([
      [0, 0],
      [5, 3],
      [1, 3],
    ]);
    expect(posed.prompt).toContain('P₃ = P₀');
    expect(posed.prompt).toContain('where is P(0.5)?');
    // Weights 1/8, 3/8, 3/8, 1/8 on (0, 0), (5, 3), (1, 3), (0, 0): ((15 + 3)/8, (9 + 9)/8) = (2.25, 2.25).
    const task = pointTask(posed);
    expect(task.figure).toBe('experiment');
    expect(task.answer[0]).toBeCloseTo(2.25, 14);
    expect(task.answer[1]).toBeCloseTo(2.25, 14);
    expect(task.check([2.4, 2.1]).correct).toBe(true);
    // Forgetting the closing copy of P₀: (0 + 2·5 + 1)/4, (0 + 2·3 + 3)/4 = (2.75, 2.25).
    const open = task.check([2.75, 2.25]);
    expect(open.correct).toBe(false);
    expect(open.message).toContain('W(3, 0, t) + W(3, 3, t) = 0.25');
  });

  it('opens at the closed polygon (no curve, no P(t)); the working ends on P(t)', () => {
    const posed = pose('closed-point', 7);
    settled(posed.state);
    const shown = modelOf('closed', posed.state).shown;
    expect(shown.has('polygon')).toBe(true);
    expect(shown.has('curve')).toBe(false);
    expect(shown.has('point')).toBe(false);
    const working = modelOf('closed', posed.working);
    expect(working.shown.has('point')).toBe(true);
    expect(working.point[0]).toBeCloseTo(2.25, 14);
  });

  it('every seed: the point summed again, hidden when the exercise opens', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('closed-point', seed);
        const task = pointTask(posed);
        const { points, t } = posed.state;
        // The closed curve's point, summed again: P₀ carries the first and the last weight.
        const n = points.length;
        const expected = [0, 1].map(
          (d) =>
            (weightOf(n, 0, t) + weightOf(n, n, t)) * points[0][d] +
            points.slice(1).reduce((sum, q, k) => sum + weightOf(n, k + 1, t) * q[d], 0),
        );
        expect(task.answer[0]).toBeCloseTo(expected[0], 12);
        expect(task.answer[1]).toBeCloseTo(expected[1], 12);
        expect(modelOf('closed', posed.state).shown.has('point')).toBe(false);
        settled(posed.state);
      }),
      { numRuns: 300 },
    ));
});

describe('close the curve without a corner', () => {
  it('seed 5: P₁ from (5, 2) to (5, 0) makes P′(0) = 4(P₁ − P₀) equal P′(1) = 4(P₀ − P₃) = (8, 0)', () => {
    const posed = pose('closed-smooth', 5);
    expect(posed.prompt).toBe(
      'Move only P₁ so that the closed curve is C¹ at P₀ = P₄: it leaves P₀ with the very velocity it arrives with, P′(0) = P′(1), within 0.4.',
    );
    expect(posed.state.points).toEqual([
      [3, 0],
      [5, 2],
      [2, 4],
      [1, 0],
    ]);
    const task = constructTask(posed);
    // Posed: P′(0) = 4·((5, 2) − (3, 0)) = (8, 8), P′(1) = 4·((3, 0) − (1, 0)) = (8, 0): 45° apart.
    expect(task.check(posed.state)).toEqual({
      correct: false,
      message:
        'Not yet: P′(0) = (8, 8) and P′(1) = (8, 0) meet at a corner of 45.0°; C¹ at P₀ needs P₁ − P₀ = P₀ − P₃.',
    });
    // P₁ = 2P₀ − P₃ = (5, 0).
    expect(task.solution.points[1]).toEqual([5, 0]);
    expect(task.check(task.solution)).toEqual({
      correct: true,
      message: 'Correct: P′(0) = (8, 0) and P′(1) = (8, 0), so the curve is C¹ at P₀.',
    });
    const withP1 = (p1: number[]) => ({
      ...posed.state,
      points: posed.state.points.map((q, i) => (i === 1 ? p1 : q)),
    });
    // In line but too far: P′(0) = (12, 0), smooth to the eye (G¹) and not C¹.
    expect(task.check(withP1([6, 0])).message).toContain('point the same way (smooth to the eye)');
    // 4·0.09 = 0.36 is within 0.4; 4·0.11 = 0.44 is not.
    expect(task.check(withP1([5.09, 0])).correct).toBe(true);
    expect(task.check(withP1([5, 0.11])).correct).toBe(false);
    expect(
      task.check({
        ...task.solution,
        points: task.solution.points.map((q, i) => (i === 3 ? [1, 1] : q)),
      }).message,
    ).toBe('Move only P₁: P₃ belongs at (1, 0).');
    expect(task.check({ ...task.solution, points: task.solution.points.slice(0, 3) }).message).toBe(
      'Keep the 4 control points P₀ … P₃ (there are 3 now).',
    );
  });

  it('opens on the whole experiment, the corner shown; the working is smooth', () => {
    const posed = pose('closed-smooth', 5);
    settled(posed.state);
    const m = modelOf('closed', posed.state);
    expect(m.shown.has('tangents')).toBe(true);
    expect(m.smooth).toBe(false);
    expect(modelOf('closed', posed.working).smooth).toBe(true);
  });

  it('every seed: the mirror of the last point through P₀ is the solution, inside the figure, and survives a finger’s slip', () =>
    fc.assert(
      fc.property(seeds, fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }), (seed, angle) => {
        const posed = pose('closed-smooth', seed);
        const task = constructTask(posed);
        const [p0, , , last] = posed.state.points;
        // P₁ − P₀ = P₀ − P₃.
        expect(task.solution.points[1]).toEqual([2 * p0[0] - last[0], 2 * p0[1] - last[1]]);
        const [x, y] = task.solution.points[1];
        const slipped = (by: number) => ({
          ...task.solution,
          points: task.solution.points.map((q, i) =>
            i === 1 ? [x + by * Math.cos(angle), y + by * Math.sin(angle)] : q,
          ),
        });
        // A finger's 0.09 off still passes (1.5% of the figure); 0.3 off does not.
        expect(task.check(slipped(0.09)).correct).toBe(true);
        expect(task.check(slipped(0.3)).correct).toBe(false);
        for (const d of [0, 1]) {
          const values = posed.state.points.map((q) => q[d]);
          expect(task.solution.points[1][d]).toBeGreaterThanOrEqual(Math.min(...values));
          expect(task.solution.points[1][d]).toBeLessThanOrEqual(Math.max(...values));
        }
        settled(posed.state);
      }),
      { numRuns: 300 },
    ));
});

describe('make the cubic turn both ways', () => {
  it('seed 4: P₂ from (3, 2) to (2, 1) gives an inflection at t = √0.4 = 0.63, worked by hand', () => {
    const posed = pose('inflection', 4);
    expect(posed.prompt).toBe(
      'Move only P₂ until the cubic turns both ways, with an inflection where its curvature changes sign.',
    );
    expect(posed.state.points).toEqual([
      [0, 1],
      [0, 3],
      [3, 2],
      [6, 0],
    ]);
    // P(t) = a0 + a1 t + a2 t² + a3 t³ and P′ × P″ = 2(a1×a2) + 6(a1×a3)t + 6(a2×a3)t².
    // Posed: a1 = 3(P1 − P0) = (0, 6), a2 = 3(P2 − 2P1 + P0) = (9, −9), a3 = P3 − 3P2 + 3P1 − P0 = (−3, 2):
    // −108 + 108t − 54t² = −54(t² − 2t + 2) < 0 for every t: no inflection.
    const task = constructTask(posed);
    expect(task.check(posed.state)).toEqual({
      correct: false,
      message:
        'Not yet: no inflection, the cubic still turns one way only. Move P₂ so the polygon bends one way at P₁ and the other way at P₂.',
    });
    // Solved: P2 = (2, 1), a2 = (6, −12), a3 = (0, 5): −72 + 0t + 180t², zero at t = √0.4 = 0.632.
    expect(task.solution.points[2]).toEqual([2, 1]);
    expect(task.check(task.solution)).toEqual({
      correct: true,
      message: 'Correct: the cubic turns both ways, with an inflection at t = 0.63.',
    });
  });

  it('says what else is off: another point moved, a loop, an inflection too near the end', () => {
    const posed = pose('inflection', 4);
    const task = constructTask(posed);
    const with2 = (p2: number[]) => ({
      ...posed.state,
      points: posed.state.points.map((q, i) => (i === 2 ? p2 : q)),
    });
    const moved = {
      ...task.solution,
      points: task.solution.points.map((q, i) => (i === 0 ? [0, 0] : q)),
    };
    expect(task.check(moved).message).toBe('Move only P₂: P₀ belongs at (0, 1).');
    // P2 = (−4, 2), far to the left of the first leg: P(t) = P(s) for two t, a loop.
    expect(task.check(with2([-4, 2])).message).toContain('that is a loop');
    // On the line P1P3 at x = 3 (y = 1.5) the inflection sits at t = 1 exactly; a hair below, just inside.
    expect(task.check(with2([3, 1.49])).message).toContain('too near the end to see');
  });

  it('opens on the whole experiment, with the turns coloured and marked', () => {
    const posed = pose('inflection', 4);
    settled(posed.state);
    const m = modelOf('cubic', posed.state);
    expect(m.shown.has('marks')).toBe(true);
    expect(m.inflections).toEqual([]);
    expect(modelOf('cubic', posed.working).inflections).toHaveLength(1);
  });

  it('every seed: the solution survives a finger’s slip of 0.3, inside the figure', () =>
    fc.assert(
      fc.property(seeds, (seed) => {
        const posed = pose('inflection', seed);
        const task = constructTask(posed);
        const k = task.solution.points.findIndex(
          (q, i) => q[0] !== posed.state.points[i][0] || q[1] !== posed.state.points[i][1],
        );
        expect(posed.prompt).toContain(`Move only P${SUBSCRIPTS[k]}`);
        for (let j = 0; j < 8; j++) {
          const [x, y] = task.solution.points[k];
          const slipped = task.solution.points.map((q, i) =>
            i === k
              ? [x + 0.3 * Math.cos((j * Math.PI) / 4), y + 0.3 * Math.sin((j * Math.PI) / 4)]
              : q,
          );
          expect(task.check({ ...task.solution, points: slipped }).correct).toBe(true);
        }
        // In the posed figure: inside the box of the points the student sees.
        for (const d of [0, 1]) {
          const values = posed.state.points.map((q) => q[d]);
          expect(task.solution.points[k][d]).toBeGreaterThanOrEqual(Math.min(...values));
          expect(task.solution.points[k][d]).toBeLessThanOrEqual(Math.max(...values));
        }
        settled(posed.state);
      }),
      { numRuns: 200 },
    ));
});
