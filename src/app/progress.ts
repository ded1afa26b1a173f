/**
 * A student's progress in practice, kept on this device only: for each
 * exercise, whether it was solved and how many checks it took. The gallery
 * reads it; nothing leaves the page.
 */
export const PROGRESS_KEY = 'spline-lab:practice';

export interface ExerciseProgress {
  /** Solved at least once. */
  done: boolean;
  /** Answers checked, right or wrong. */
  tries: number;
}

export interface Progress {
  /** By `slug/exercise`. */
  exercises: Record<string, ExerciseProgress>;
  /** How many exercises each lesson has, as last seen (the gallery has no lesson code). */
  totals: Record<string, number>;
}

const empty = (): Progress => ({ exercises: {}, totals: {} });

export function readProgress(storage: Storage | null = safeStorage()): Progress {
  try {
    const raw = storage?.getItem(PROGRESS_KEY);
    if (!raw) return empty();
    const parsed = JSON.parse(raw) as Partial<Progress>;
    const progress = empty();
    for (const [key, value] of Object.entries(parsed.exercises ?? {}))
      if (value && typeof value.tries === 'number' && typeof value.done === 'boolean')
        progress.exercises[key] = { done: value.done, tries: value.tries };
    for (const [slug, total] of Object.entries(parsed.totals ?? {}))
      if (typeof total === 'number') progress.totals[slug] = total;
    return progress;
  } catch {
    // Damaged or unreadable: start again rather than fail the page.
    return empty();
  }
}

function write(progress: Progress, storage: Storage | null): void {
  try {
    storage?.setItem(PROGRESS_KEY, JSON.stringify(progress));
  } catch {
    // Storage full or refused (private mode): progress is simply not kept.
  }
}

/** One checked answer: counts the try, and marks the exercise done when right. */
export function recordTry(
  slug: string,
  id: string,
  correct: boolean,
  storage: Storage | null = safeStorage(),
): ExerciseProgress {
  const progress = readProgress(storage);
  const key = `${slug}/${id}`;
  const before = progress.exercises[key] ?? { done: false, tries: 0 };
  const after = { done: before.done || correct, tries: before.tries + 1 };
  progress.exercises[key] = after;
  write(progress, storage);
  return after;
}

/** Remembers how many exercises a lesson has, for the gallery. */
export function recordTotal(slug: string, total: number, storage: Storage | null = safeStorage()) {
  const progress = readProgress(storage);
  if (progress.totals[slug] === total) return;
  progress.totals[slug] = total;
  write(progress, storage);
}

/** A lesson's progress: exercises solved, and how many it has (0 if never opened). */
export function lessonProgress(slug: string, progress: Progress = readProgress()) {
  const done = Object.entries(progress.exercises).filter(
    ([key, value]) => key.startsWith(`${slug}/`) && value.done,
  ).length;
  return { done, total: progress.totals[slug] ?? 0 };
}

function safeStorage(): Storage | null {
  try {
    return typeof localStorage === 'undefined' ? null : localStorage;
  } catch {
    return null;
  }
}
