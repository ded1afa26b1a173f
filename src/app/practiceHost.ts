/**
 * A lesson page's practice: the card (practice.ts), the button that opens it,
 * the exercise a link names, and "Show me", which walks an exercise's working
 * step by step on the page's own figure.
 */
import type { ExerciseSpec } from '../kit/exercise';
import { h, setHidden } from './dom';
import type { AnyLesson } from './lesson';
import { type LessonStore, type Loaded, normalizeState, sceneIndexOf } from './lessonState';
import { Practice } from './practice';
import type { ScriptWalker } from './scriptWalker';
import { defaultsOf, type PracticeLink, type Schema } from './urlState';

/** What the page lends its practice. */
export interface PracticePage<S> {
  lesson: AnyLesson;
  store: LessonStore<S>;
  walker: ScriptWalker<S>;
  /** The page's element and its figures' box (built after the practice). */
  element(): HTMLElement;
  figureBox(): HTMLElement;
  /** The titles of the figures shown now, by id. */
  shownFigureIds(): string[];
  fit(): void;
  redraw(): void;
  linkChanged(): void;
}

export class PracticeHost<S> {
  readonly practice: Practice<S>;
  /** The button that opens practice, at the top of the panel. */
  readonly entry: HTMLElement;
  /** The working being walked step by step ("Show me"), or 0. */
  private walking = 0;

  /** The practice of a lesson with exercises; undefined for a lesson without any. */
  static of<S>(page: PracticePage<S>, loaded: Loaded<S>): PracticeHost<S> | undefined {
    const exercises = page.lesson.exercises as readonly ExerciseSpec<S>[] | undefined;
    return exercises?.length ? new PracticeHost(page, exercises, loaded) : undefined;
  }

  private constructor(
    private readonly page: PracticePage<S>,
    exercises: readonly ExerciseSpec<S>[],
    loaded: Loaded<S>,
  ) {
    const lesson = page.lesson;
    const practice = new Practice<S>(exercises, {
      slug: lesson.slug,
      defaults: defaultsOf(lesson.schema as Schema<S>),
      get: () => page.store.state,
      open: (state, scene) => {
        this.stopWalk();
        this.enterScene(scene, state);
        page.store.set(normalizeState(lesson, state).state);
        page.fit();
      },
      walk: (state, scene) => this.walk(state, scene),
      redraw: () => page.redraw(),
      linkChanged: () => page.linkChanged(),
      toggled: (open) => {
        setHidden(this.entry, open);
        page.element().classList.toggle('practising', open);
        // A phone: the figure shares the first screen with the question.
        if (open && window.matchMedia?.('(max-width: 820px)').matches)
          requestAnimationFrame(() => page.figureBox().scrollIntoView({ block: 'start' }));
      },
      tappable: (id) => lesson.figures.find((f) => f.id === id)?.kind !== 'space',
      quiet: (on) => page.element().classList.toggle('practice-quiet', on),
      figureTitle: (id) => {
        const title = lesson.figures.find((f) => f.id === id)?.title;
        return page.shownFigureIds().length > 1 && title ? `the figure “${title}”` : 'the figure';
      },
    });
    this.practice = practice;
    this.entry = h(
      'div',
      { class: 'practice-entry' },
      h(
        'button',
        {
          type: 'button',
          class: 'primary',
          onclick: () => practice.start(exercises[0].id, loaded.practice?.seed ?? 1),
        },
        'Practice',
      ),
      h(
        'span',
        {},
        ` ${exercises.length} exercises: predict a point, compute a number, make a curve. Checked as you go.`,
      ),
    );
    if (loaded.practice) {
      const { id, seed, kept } = loaded.practice;
      // After the page is built: the exercise sets the state and the scene
      // (the figure the link kept, if it kept one: the student's own work).
      queueMicrotask(() => practice.start(id, seed, kept ? loaded.state : undefined));
    }
  }

  /** The exercise and seed the link carries, or null when no exercise is open. */
  link(): PracticeLink | null {
    return this.practice.link();
  }

  /**
   * A link typed into the address bar or reached by back/forward: true when it
   * was an exercise's and is applied; otherwise an open exercise is closed.
   */
  applyLink(loaded: Loaded<S>): boolean {
    if (loaded.practice) {
      const { id, seed, kept } = loaded.practice;
      const now = this.practice.link();
      if (now?.id !== id || now.seed !== seed)
        this.practice.start(id, seed, kept ? loaded.state : undefined);
      else if (kept) this.page.store.set(loaded.state);
      return true;
    }
    if (this.practice.active) this.practice.close();
    return false;
  }

  /**
   * "Show me": opens the working at step 0 and walks its steps, one a second
   * (at once with reduced motion). Any other change of state stops the walk.
   */
  private walk(state: S, scene: string | undefined): void {
    const { lesson, store, walker } = this.page;
    this.stopWalk();
    this.enterScene(scene, state);
    const key = lesson.steps?.key as keyof S | undefined;
    const start = key === undefined ? state : ({ ...state, [key]: 0 } as S);
    store.set(normalizeState(lesson, start).state);
    this.page.fit();
    const reduced = window.matchMedia?.('(prefers-reduced-motion: reduce)').matches ?? false;
    let walked = store.state;
    const tick = () => {
      const { k, count } = walker.stepOf(store.state);
      // Done, or the student took over (moved a point, pressed Back): stop.
      if (k >= count || store.state !== walked) {
        this.walking = 0;
        return;
      }
      store.set({ ...store.state, [key as keyof S]: reduced ? count : k + 1 } as S, {
        record: false,
      });
      walked = store.state;
      this.walking = window.setTimeout(tick, 900);
    };
    if (key !== undefined) this.walking = window.setTimeout(tick, reduced ? 0 : 700);
  }

  /**
   * The scene an exercise is set in becomes the walker's: the one it names,
   * else the one its state is in (see `sceneIndexOf`).
   */
  private enterScene(id: string | undefined, state: S): void {
    const lesson = this.page.lesson;
    const named = (lesson.scenes ?? []).findIndex((scene) => scene.id === id);
    this.page.walker.restart(sceneIndexOf(lesson, state, named));
  }

  stopWalk(): void {
    window.clearTimeout(this.walking);
    this.walking = 0;
  }
}
