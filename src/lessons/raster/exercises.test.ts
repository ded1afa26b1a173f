import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import type { Posed } from '../../kit/exercise';
import { checkExercises, checkPracticeData, dragOnFigures, seeds } from '../../kit/exerciseChecks';
import type { Point } from '../../math';
import { exercises } from './exercises';
import { GAP_TOLERANCE } from './farthestPointExercise';
import { FLATNESS_TOLERANCE } from './flatnessExercise';
import { PIXEL_TOLERANCE } from './nextPixelExercise';
import { SPLIT_TOLERANCE } from './twoSegmentsExercise';
import data from '../../../tests/e2e/practice/raster';
import lesson from './lesson';
import type { RasterModel } from './model';
import { subdivideScript } from './flatteningScripts';
import { RASTER_HEIGHT, RASTER_WIDTH, type RasterState, schema } from './state';

const defaults = defaultsOf(schema);
const derive = (s: RasterState) => lesson.derive(s) as RasterModel;
const lastStep = (s: RasterState) => lesson.steps!.count(s);
const curve = lesson.figures.find((f) => f.id === 'curve')!;
const pose = (id: string, seed: number) => exercises.find((e) => e.id === id)!.pose(seed, defaults);
const gap = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);
const formulaAt = (s: RasterState, step: number) => {
  const at = { ...s, step };
  return lesson.steps!.formula!(derive(at), at) ?? '';
};

function task<K extends 'point' | 'number' | 'construct'>(posed: Posed<RasterState>, kind: K) {
  if (posed.task.kind !== kind) throw new Error(`a ${kind} task, not ${posed.task.kind}`);
  return posed.task as Extract<Posed<RasterState>['task'], { kind: K }>;
}

const onRaster = (p: readonly number[]) =>
  p[0] >= 0 && p[0] <= RASTER_WIDTH && p[1] >= 0 && p[1] <= RASTER_HEIGHT;

/** Drags a control point on the curve figure, as the browser test does. */
const drag = (s: RasterState, handle: string, to: Point) =>
  curve.moveHandle!(s, handle, to, derive(s));

describe('the raster exercises', () => {
  it('are the lesson’s, and pass the kit’s checks, the point to guess on the raster', () => {
    expect(lesson.exercises).toBe(exercises);
    checkExercises(exercises, defaults, { inFigure: (_, answer) => onRaster(answer) });
  });

  it('pose states the link can hold, on the raster', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        for (const e of exercises) {
          const posed = e.pose(seed, defaults);
          for (const s of [posed.state, posed.working]) {
            expect(lesson.normalize!(s).state).toEqual(s);
            expect(s.step).toBeLessThanOrEqual(lastStep(s));
            expect(s.points.every(onRaster)).toBe(true);
          }
          expect(posed.working.step).toBe(0);
        }
      }),
      { numRuns: 60 },
    );
  });
});

describe('Where does the curve stray furthest from its segment?', () => {
  // Seed 1: P₀ (4, 14), P₁ (14, 5), P₂ (30, 18). Off the chord, P(t) − chord point = 2t(1 − t)(P₁ − M):
  // furthest at t = ½, P(½) = (P₀ + 2P₁ + P₂)/4 = (4 + 28 + 30, 14 + 10 + 18)/4 = (15.5, 10.5).
  const posed = pose('farthest-point', 1);
  const point = task(posed, 'point');

  it('poses the control points, and P(½) by hand', () => {
    expect(posed.prompt).toContain('P₀ (4, 14), P₁ (14, 5) and P₂ (30, 18)');
    expect(point.answer).toEqual([15.5, 10.5]);
    expect(point.tolerance).toBe(GAP_TOLERANCE);
  });

  it('accepts P(½), rejects a point 1.5 px off, and names the slips', () => {
    expect(point.check([15.3, 10.6]).correct).toBe(true);
    expect(point.check([15.5, 12]).correct).toBe(false);
    expect(point.check([14, 5]).message).toContain('P₁ is off the curve');
    // The chord's middle (17, 16).
    expect(point.check([17, 16]).message).toContain('on the segment itself');
  });

  it('shows no curve at the start; the working’s last step marks the largest gap at P(½)', () => {
    expect(derive(posed.state).shown.has('curve')).toBe(false);
    const end = derive({ ...posed.working, step: lastStep(posed.working) });
    expect(end.shown.has('gap')).toBe(true);
    expect(end.uniform.points).toHaveLength(2);
    expect(gap(end.uniform.deviation.point, point.answer)).toBeLessThan(1e-6);
  });

  it('has the lesson’s gap at P(½), and P₁ never passes, for every seed', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const p = pose('farthest-point', seed);
        const t = task(p, 'point');
        const deviation = derive({ ...p.working, step: lastStep(p.working) }).uniform.deviation;
        expect(deviation.t).toBeCloseTo(0.5, 6);
        // P₁ is never close enough to pass.
        expect(t.check(p.state.points[1]).correct).toBe(false);
      }),
    );
  });
});

describe('Which pixel comes next?', () => {
  // Seed 1: from pixel (22, 8) to (31, 7): x changes by 9, y by −1, so step along x.
  // At x = 29 the ideal line is at y = 8 − 7/9 = 7.22: the nearest row is 7, so (29, 7).
  const posed = pose('next-pixel', 1);
  const numbers = task(posed, 'number');
  // Seed 6, steep: from (4, 8) to (3, 17), step along y. At y = 13: x = 4 − 5/9 = 3.44, so (3, 13).
  const steep = pose('next-pixel', 6);

  it('poses the segment and the pixel before, and the next pixel by hand', () => {
    expect(posed.prompt).toContain('from pixel (22, 8) to pixel (31, 7)');
    expect(posed.prompt).toContain('after (28, 7)');
    expect(posed.state.points).toEqual([
      [22.5, 8.5],
      [31.5, 7.5],
    ]);
    expect(numbers.answer).toEqual([29, 7]);
    expect(steep.prompt).toContain('from pixel (4, 8) to pixel (3, 17)');
    expect(steep.prompt).toContain('after (4, 12)');
    expect(task(steep, 'number').answer).toEqual([3, 13]);
  });

  it('accepts the pixel, rejects the ideal crossing, and names each slip', () => {
    expect(numbers.check([29, 7]).correct).toBe(true);
    expect(numbers.check([29, 7.22]).correct).toBe(false);
    // Cut off instead of rounded: 8 − 0 = 8.
    expect(numbers.check([29, 8]).message).toContain('y = 7.222: take the nearest row');
    expect(numbers.check([28, 6]).message).toContain('Step along the longer axis, x');
    const steepTask = task(steep, 'number');
    expect(steepTask.check([4, 13]).message).toContain('x = 3.444: take the nearest column');
    expect(steepTask.check([3, 12]).message).toContain('Step along the longer axis, y');
    expect(numbers.check([30, 9]).message).toContain('Step x by one');
  });

  it('lights no pixel at the start; the working steps to the pixel with its rounding', () => {
    expect(posed.state.view).toBe('plot');
    expect(posed.working.view).toBe('pixels');
    // Step 0 the raster, 1 the ends, then one pixel a press: pixel k + 1 = 7 at step 2 + 7.
    const m = derive({ ...posed.working, step: 9 });
    expect(m.line.pixels.slice(0, m.pixelsShown).at(-1)).toEqual([29, 7]);
    expect(formulaAt(posed.working, 9)).toBe('x = 29:\\ y = 7.22 \\to 7');
  });

  it('is one right pair of whole numbers on the raster for every seed', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const t = task(pose('next-pixel', seed), 'number');
        expect(PIXEL_TOLERANCE).toBe(0);
        expect(t.answer.every(Number.isInteger)).toBe(true);
        expect(onRaster(t.answer)).toBe(true);
        expect(t.check([t.answer[0], t.answer[1] + 1]).correct).toBe(false);
        expect(t.check([t.answer[0] - 1, t.answer[1]]).correct).toBe(false);
      }),
    );
  });
});

describe('How far can the curve be from its chord?', () => {
  // Seed 1: P₀ (13, 13), P₁ (17, 14), P₂ (19, 12), P₃ (16, 9).
  // P₂ − 2P₁ + P₀ = (−2, −3), length √13 = 3.606; P₃ − 2P₂ + P₁ = (−5, −1), length √26 = 5.099.
  // Flatness 3·2/8 · √26 = 3.824.
  const posed = pose('flatness', 1);
  const numbers = task(posed, 'number');
  const [root13, root26] = [Math.sqrt(13), Math.sqrt(26)];

  it('poses the four control points, and the flatness by hand', () => {
    expect(posed.prompt).toContain('P₀ (13, 13), P₁ (17, 14), P₂ (19, 12) and P₃ (16, 9)');
    expect(numbers.answer[0]).toBeCloseTo(0.75 * root26, 12);
    expect(numbers.tolerance).toBe(FLATNESS_TOLERANCE);
  });

  it('accepts 3.82, rejects 3.85, and names each slip', () => {
    expect(numbers.check([3.82]).correct).toBe(true);
    expect(numbers.check([3.85]).correct).toBe(false);
    expect(numbers.check([root26]).message).toContain('max‖Δ²P‖ alone');
    expect(numbers.check([1.5 * root26]).message).toContain('n is the degree');
    expect(numbers.check([0.75 * root13]).message).toContain('Take the larger');
    expect(numbers.check([0.75 * (root13 + root26)]).message).toContain('not their sum');
  });

  it('shows the test without its numbers at the start; the first visit gives the flatness', () => {
    expect(posed.state.view).toBe('subdivide');
    expect(formulaAt(posed.state, 0)).not.toContain('3.82');
    expect(formulaAt(posed.working, 1)).toContain('= 3.82\\ >');
  });

  it('is the flatness worked again for every seed, and the working’s first visit is the whole curve', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const p = pose('flatness', seed);
        const t = task(p, 'number');
        // Independently: 3·2/8 times the longer second difference.
        const q = p.state.points;
        const second = (i: number) =>
          Math.hypot(
            q[i + 2][0] - 2 * q[i + 1][0] + q[i][0],
            q[i + 2][1] - 2 * q[i + 1][1] + q[i][1],
          );
        expect(t.answer[0]).toBeCloseTo(0.75 * Math.max(second(0), second(1)), 9);
        // The whole curve is split (flatness > τ), and the first press visits it.
        expect(subdivideScript.stepOf(p.working, 'pieces')).toBe(1);
        expect(derive({ ...p.working, step: 1 }).piecesShown).toBe(1);
      }),
    );
  });
});

describe('Exactly two segments', () => {
  // Seed 1: P₀ (10, 7), P₂ (26, 13), their middle M = (18, 10); posed P₁ (16, 4).
  // Flatness of a quadratic: 2·1/8 · ‖P₀ − 2P₁ + P₂‖ = ½‖P₁ − M‖.
  // Posed: ½‖(−2, −6)‖ = 3.16 > τ = 0.5, halves a quarter of it, 0.79 > τ: 4 segments.
  // P₁ at (17, 7): ½‖(−1, −3)‖ = 1.58 > τ, halves 0.395 ≤ τ: 2 segments.
  const posed = pose('two-segments', 1);
  const construct = task(posed, 'construct');

  it('opens with four segments and says why, with the numbers', () => {
    expect(posed.prompt).toContain('Keep P₀ (10, 7) and P₂ (26, 13)');
    expect(posed.state.points).toEqual([
      [10, 7],
      [16, 4],
      [26, 13],
    ]);
    expect(posed.state.tolerance).toBe(SPLIT_TOLERANCE);
    const verdict = construct.check(posed.state);
    expect(verdict.correct).toBe(false);
    expect(verdict.message).toContain('4 segments');
    expect(verdict.message).toContain('flatness is 3.162 px');
  });

  it('passes once P₁ is dragged to (17, 7), and says which way to go otherwise', () => {
    expect(construct.check(drag(posed.state, 'p1', [17, 7])).correct).toBe(true);
    // On the chord's middle: flatness 0, one segment.
    expect(construct.check(drag(posed.state, 'p1', [18, 10])).message).toContain('Move P₁ further');
    expect(construct.check(drag(posed.state, 'p0', [11, 7])).message).toContain('Move only P₁');
  });

  it('is solvable by one drag on the raster, for every seed', () => {
    fc.assert(
      fc.property(seeds, (seed) => {
        const p = pose('two-segments', seed);
        const t = task(p, 'construct');
        const target = t.solution.points[1];
        expect(onRaster(target)).toBe(true);
        expect(t.check(drag(p.state, 'p1', target)).correct).toBe(true);
        // A finger's slip of 0.5 px anywhere still passes: the band is 1 to 4 px from M.
        expect(t.check(drag(p.state, 'p1', [target[0] + 0.5, target[1]])).correct).toBe(true);
        expect(derive(t.solution).adaptive.points).toHaveLength(3);
      }),
    );
  });
});

describe('the browser test’s practice data', () => {
  it('matches each posed prompt, and its answers pass where its wrong answers fail', () => {
    checkPracticeData(exercises, defaults, data, dragOnFigures(lesson));
  });
});
