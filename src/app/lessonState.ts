import { History, type HistoryOptions } from './history';
import type { AnyLesson } from './lesson';
import { decodeState, defaultsOf, encodeState } from './urlState';

/** Key under which the last state of a lesson is kept in localStorage. */
export const storageKey = (slug: string) => `spline-lab:lesson:${slug}`;

export interface Loaded<S> {
  state: S;
  issues: string[];
  /** Views of figures the link or the stored state carries (`view.<figure>`). */
  views: Record<string, string>;
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
  if (query !== '') {
    const decoded = decodeState<S>(lesson.schema, query, figures);
    const normalized = normalizeState(lesson, decoded.state);
    return {
      state: normalized.state as S,
      issues: [...decoded.issues, ...normalized.issues],
      views: decoded.views,
    };
  }
  const stored = readStorage(storage, storageKey(lesson.slug));
  if (stored) {
    const decoded = decodeState<S>(lesson.schema, stored, figures);
    if (decoded.issues.length === 0)
      return {
        state: normalizeState(lesson, decoded.state).state as S,
        issues: [],
        views: decoded.views,
      };
  }
  // Defaults go through the same rules, so a lesson may default a step to "the end".
  return {
    state: normalizeState(lesson, defaultsOf<S>(lesson.schema)).state,
    issues: [],
    views: {},
  };
}

function readStorage(storage: Storage | null, key: string): string | null {
  try {
    return storage?.getItem(key) ?? null;
  } catch {
    return null;
  }
}

/** A lesson's state with undo/redo and change listeners. */
export class LessonStore<S> {
  private readonly history: History<S>;
  private readonly listeners = new Set<(state: S) => void>();

  constructor(
    private readonly lesson: AnyLesson,
    initial: S,
  ) {
    this.history = new History(initial);
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

  /** The state as it appears in the URL after `#/slug?`, with the figures' views. */
  query(views: Readonly<Record<string, string>> = {}): string {
    return encodeState(this.lesson.schema, this.state, views);
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
    this.history.undo();
    this.emit();
  }

  redo(): void {
    this.history.redo();
    this.emit();
  }

  private emit(): void {
    for (const listener of this.listeners) listener(this.state);
  }
}
