import type { FigureSpec, LessonDefinition } from '../src/app/lesson';
import { defaultsOf } from '../src/app/urlState';

/**
 * A lesson's scene `scene` opened as its link opens it, at `step` (its last
 * step unless given): the state, its model, and the lesson's figure `figure`.
 */
export function sceneStep<S extends { step: number }, M>(
  lesson: LessonDefinition<S, M>,
  scene: string,
  figure: string,
  step?: number,
): { state: S; model: M; figure: FigureSpec<S, M> } {
  const opened = lesson.scenes!.find((s) => s.id === scene)!;
  const start = opened.apply(defaultsOf(lesson.schema) as S) as S;
  const state = { ...start, step: step ?? lesson.steps!.count(start) };
  return {
    state,
    model: lesson.derive(state),
    figure: lesson.figures.find((f) => f.id === figure)!,
  };
}
