/**
 * The checks every lesson's exercises pass, over every seed: the kit's
 * promises about an exercise, kept in one place (as scriptChecks.ts keeps a
 * script's). A lesson's own tests add what only it can know: numbers worked
 * by hand, its typical slips and their hints.
 */
import fc from 'fast-check';
import { expect } from 'vitest';
import type { FigureSpec } from '../app/lesson';
import type { Point } from '../math';
import type { PracticeCase } from '../../tests/e2e/practice/types';
import { MAX_SEED, type ExerciseSpec } from './exercise';

/** Any seed a link may carry. */
export const seeds = fc.integer({ min: 1, max: MAX_SEED });

/** Sentences in a prompt (a full stop or question mark followed by a space or the end). */
export const sentences = (text: string) => (text.match(/[.?!](\s|$)/g) ?? []).length;

export interface ExerciseCheckOptions<S> {
  /** Runs per property (fast-check's numRuns); 100 by default. */
  runs?: number;
  /** Is a point inside the figure's sensible area (the guess is asked of a point on screen)? */
  inFigure?(state: S, point: Point, figure: string): boolean;
}

/**
 * Over seeds: the same seed poses the same exercise (its state, its working
 * and its task's answer, to the letter); the prompt is plain words of at most
 * two sentences; a number answer is finite and accepted, and 3× the tolerance
 * off is not (one off, where the answer is exact); a point answer is
 * accepted, and a guess 3× the tolerance away is not; a construction's
 * solution passes and the opening figure does not.
 */
export function checkExercises<S>(
  exercises: readonly ExerciseSpec<S>[],
  defaults: S,
  options: ExerciseCheckOptions<S> = {},
): void {
  expect(exercises.length).toBeGreaterThanOrEqual(3);
  expect(new Set(exercises.map((e) => e.kind))).toEqual(new Set(['point', 'number', 'construct']));
  expect(new Set(exercises.map((e) => e.id)).size).toBe(exercises.length);
  fc.assert(
    fc.property(seeds, fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }), (seed, angle) => {
      for (const exercise of exercises) {
        const posed = exercise.pose(seed, defaults);
        const again = exercise.pose(seed, defaults);
        expect(again.prompt).toBe(posed.prompt);
        expect(again.state).toEqual(posed.state);
        expect(again.working).toEqual(posed.working);
        // The rest a link and "Show me" rely on (the answer, the solution, the marks).
        expect(JSON.stringify(again)).toBe(JSON.stringify(posed));
        expect(posed.prompt).not.toMatch(/[\\$]/);
        expect(sentences(posed.prompt)).toBeLessThanOrEqual(2);
        const task = posed.task;
        expect(task.kind).toBe(exercise.kind);
        if (task.kind === 'number') {
          expect(task.answer.every(Number.isFinite)).toBe(true);
          expect(task.fields.length).toBe(task.answer.length);
          expect(task.check(task.answer).correct).toBe(true);
          const off = 3 * task.tolerance || 1;
          expect(task.check(task.answer.map((v) => v + off)).correct).toBe(false);
        } else if (task.kind === 'point') {
          expect(task.check(task.answer).correct).toBe(true);
          const off = [Math.cos(angle), Math.sin(angle)].map(
            (d, i) => task.answer[i] + 3 * task.tolerance * d,
          );
          expect(task.check(off).correct).toBe(false);
          if (options.inFigure)
            expect(options.inFigure(posed.state, task.answer, task.figure)).toBe(true);
        } else {
          expect(task.check(task.solution).correct).toBe(true);
          expect(task.check(posed.state).correct).toBe(false);
        }
      }
    }),
    { numRuns: options.runs ?? 100 },
  );
}

/**
 * The browser test's practice data agrees with the exercises: every exercise
 * has a case, the prompt says what the case says, the hand-worked answer is
 * accepted and the wrong one is not, and the named drags, made with the
 * lesson's own `moveHandle`, solve the construction.
 */
export function checkPracticeData<S>(
  exercises: readonly ExerciseSpec<S>[],
  defaults: S,
  cases: readonly PracticeCase[],
  drag: (state: S, figure: string, handle: string, to: Point) => S,
): void {
  expect(new Set(cases.map((c) => c.id))).toEqual(new Set(exercises.map((e) => e.id)));
  for (const { id, seed, prompt, answer } of cases) {
    const posed = exercises.find((e) => e.id === id)!.pose(seed, defaults);
    for (const text of prompt) expect(posed.prompt).toContain(text);
    const { task } = posed;
    if ('point' in answer && task.kind === 'point')
      expect(task.check([...answer.point]).correct).toBe(true);
    else if ('numbers' in answer && task.kind === 'number') {
      expect(task.check(answer.numbers).correct).toBe(true);
      expect(task.check(answer.wrong).correct).toBe(false);
    } else if ('moves' in answer && task.kind === 'construct') {
      const end = answer.moves.reduce(
        (state, { figure, handle, to }) => drag(state, figure, handle, [...to]),
        posed.state,
      );
      expect(task.check(end).correct).toBe(true);
    } else throw new Error(`${id}: the case's answer is not of the task's kind (${task.kind})`);
  }
}

/**
 * The browser test's drag, made with the lesson's own figures (for
 * `checkPracticeData`): the handle is on its figure and moves to `to`; in
 * space (a handle at [x, y, z]) along x and y only, its height kept, as the
 * test's arrow keys move it.
 */
export function dragOnFigures<S, M>(lesson: {
  figures: readonly FigureSpec<S, M>[];
  derive(state: S): M;
}): (state: S, figure: string, handle: string, to: Point) => S {
  return (state, figure, handle, to) => {
    const spec = lesson.figures.find((f) => f.id === figure);
    expect(spec?.moveHandle, `figure ${figure} moves its handles`).toBeDefined();
    const model = lesson.derive(state);
    const at = spec!.handles?.(model).find((h) => h.id === handle);
    expect(at, `handle ${handle} on figure ${figure}`).toBeDefined();
    const target = at!.position.length === 3 ? [to[0], to[1], at!.position[2]] : to;
    return spec!.moveHandle!(state, handle, target, model);
  };
}
