import { History, type HistoryOptions } from './history';
import type { AnyLesson } from './lesson';
import {
  type Decoded,
  decodeState,
  defaultsOf,
  encodeState,
  keyOf,
  type PracticeLink,
} from './urlState';

/** Key under which the last state of a lesson is kept in localStorage. */
export const storageKey = (slug: string) => `spline-lab:lesson:${slug}`;

export interface Loaded<S> {
  state: S;
  issues: string[];
  /** Views of figures the link or the stored state carries (`view.<figure>`). */
  views: Record<string, string>;
  /** The scene of the lesson's script it is in (an index into `lesson.scenes`). */
  scene: number;
  /** The exercise the link opens, or null. */
  practice?: PracticeLink | null;
}

/** Applies the lesson's own cross-field rules and the shell's step clamp. */
export function normalizeState<S>(lesson: AnyLesson, state: S): { state: S; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  if (lesson.normalize) {
    const result = lesson.normalize(next);
    next = result.state;
    issues.push(...result.issues);
  }
  if (lesson.steps) {
    const key = lesson.steps.key as keyof S;
    const count = lesson.steps.count(next);
    const step = next[key] as unknown as number;
    if (step > count) {
      next = { ...next, [key]: count };
      issues.push(
        `${keyOf(lesson.schema, key as keyof S & string)}: ${step} is past the last step of this construction (${count}), so it shows step ${count}`,
      );
    }
  }
  return { state: next, issues };
}

/**
 * Chooses the state a lesson opens with: the link's state if it has one,
 * else the last state kept on this device, else the lesson's defaults.
 * Problems with the link are returned as issues to show; a stale stored state
 * is dropped quietly.
 */
export function loadState<S>(lesson: AnyLesson, query: string, storage: Storage | null): Loaded<S> {
  const figures = lesson.figures.map((f) => f.id);
  const scenes = (lesson.scenes ?? []).map((scene) => scene.id);
  const exercises = (lesson.exercises ?? []).map((exercise) => exercise.id);
  if (query !== '') {
    const decoded = decodeState<S>(lesson.schema, query, figures, scenes, exercises);
    const normalized = normalizeState(lesson, overScene(lesson, decoded));
    return {
      state: normalized.state as S,
      issues: [...decoded.issues, ...normalized.issues],
      views: decoded.views,
      scene: sceneIndexOf(lesson, normalized.state, decoded.sceneNamed ? decoded.scene : -1),
      practice: decoded.practice,
    };
  }
  const stored = readStorage(storage, storageKey(lesson.slug));
  let issues: string[] = [];
  if (stored) {
    const decoded = decodeState<S>(lesson.schema, stored, figures, scenes, exercises);
    if (decoded.issues.length === 0) {
      const state = normalizeState(lesson, decoded.state).state as S;
      return {
        state,
        issues: [],
        views: decoded.views,
        scene: sceneIndexOf(lesson, state, decoded.sceneNamed ? decoded.scene : -1),
        practice: decoded.practice,
      };
    }
    // Kept by an older version, or damaged: say so rather than lose it quietly.
    issues = [
      `the state this device kept from your last visit could not be read (${decoded.issues[0]}), so the lesson opened with its defaults`,
    ];
  }
  // Defaults go through the same rules, so a lesson may default a step to "the end".
  return {
    state: normalizeState(lesson, defaultsOf<S>(lesson.schema)).state,
    issues,
    views: {},
    scene: 0,
  };
}

/**
 * The scene a state is in (an index into `lesson.scenes`): the scene `named`
 * (a link's `scene=`, an exercise's) if the state walks that scene's steps;
 * else, among the scenes whose steps it walks, the one whose setup it is
 * nearest (most fields alike). A link written by hand, `x=compare&step=4`,
 * opens the scene it shows, so the caption's "scene k/n", the pressed scene
 * button and the clicker's next scene say where the picture is.
 */
export function sceneIndexOf<S>(lesson: AnyLesson, state: S, named = -1): number {
  const scenes = lesson.scenes ?? [];
  if (scenes.length === 0) return 0;
  const defaults = defaultsOf<S>(lesson.schema);
  const familyOf = (s: S) => (lesson.sceneOf as ((s: S) => string | undefined) | undefined)?.(s);
  const family = familyOf(state);
  const setups = scenes.map((scene) => scene.apply(defaults) as S);
  const walks = (i: number) => familyOf(setups[i]) === family;
  if (named >= 0 && named < scenes.length && walks(named)) return named;
  const fields = Object.keys(lesson.schema).filter((name) => name !== lesson.steps?.key);
  const alike = (setup: S) =>
    fields.filter(
      (name) => JSON.stringify(setup[name as keyof S]) === JSON.stringify(state[name as keyof S]),
    ).length;
  let best = -1;
  for (let i = 0; i < scenes.length; i++)
    if (walks(i) && (best < 0 || alike(setups[i]) > alike(setups[best]))) best = i;
  return best >= 0 ? best : Math.max(0, Math.min(named, scenes.length - 1));
}

/**
 * The link's state, read over its scene's setup when it names one: `scene=runge`
 * alone opens the Runge scene's points, and any field the link gives wins.
 */
function overScene<S>(lesson: AnyLesson, decoded: Decoded<S>): S {
  const scene = lesson.scenes?.[decoded.scene];
  if (!decoded.sceneNamed || !scene) return decoded.state;
  const opened = { ...(scene.apply(defaultsOf<S>(lesson.schema)) as S) };
  // A scene opens at its step 0, as its button opens it.
  if (lesson.steps) (opened as Record<string, unknown>)[lesson.steps.key] = 0;
  for (const name of decoded.given) opened[name] = decoded.state[name];
  return opened;
}

function readStorage(storage: Storage | null, key: string): string | null {
  try {
    return storage?.getItem(key) ?? null;
  } catch {
    return null;
  }
}

/**
 * A lesson's state with undo/redo and change listeners, and where it is in the
 * lesson's script. Undo and redo are for edits: they never move the step (the
 * clicker is not an edit), so they keep the step in force.
 */
export class LessonStore<S> {
  private readonly history: History<S>;
  private readonly listeners = new Set<(state: S) => void>();
  /** The current scene of the script (an index into `lesson.scenes`). */
  scene: number;

  constructor(
    private readonly lesson: AnyLesson,
    initial: S,
    scene = 0,
  ) {
    this.history = new History(initial);
    this.scene = scene;
  }

  get state(): S {
    return this.history.state;
  }

  get canUndo() {
    return this.history.canUndo;
  }
  get canRedo() {
    return this.history.canRedo;
  }

  /** The state as it appears in the URL after `#/slug?`, with the scene and the figures' views. */
  query(views: Readonly<Record<string, string>> = {}): string {
    const scene = this.lesson.scenes?.[this.scene]?.id;
    return encodeState(this.lesson.schema, this.state, views, scene);
  }

  subscribe(listener: (state: S) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  set(next: S, options: HistoryOptions & { record?: boolean } = {}): string[] {
    const { state, issues } = normalizeState(this.lesson, next);
    if (options.record === false) this.history.replace(state);
    else this.history.push(state, options);
    this.emit();
    return issues;
  }

  undo(): void {
    const step = this.step();
    this.history.undo();
    this.keepStep(step);
    this.emit();
  }

  redo(): void {
    const step = this.step();
    this.history.redo();
    this.keepStep(step);
    this.emit();
  }

  private step(): number | null {
    const key = this.lesson.steps?.key;
    return key === undefined ? null : (this.state as Record<string, number>)[key];
  }

  private keepStep(step: number | null): void {
    const key = this.lesson.steps?.key;
    if (key === undefined || step === null || this.step() === step) return;
    this.history.replace(normalizeState(this.lesson, { ...this.state, [key]: step }).state as S);
  }

  private emit(): void {
    for (const listener of this.listeners) listener(this.state);
  }
}
