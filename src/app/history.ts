/**
 * Undo/redo over immutable states. A burst of changes that belong together (one
 * drag, a run of arrow-key presses on one point) shares a coalesce key and
 * becomes one undo step.
 */
export interface HistoryOptions {
  /** Changes with the same key in a row replace each other instead of stacking. */
  coalesce?: string;
  /** With `coalesce`: only merge when the previous change is at most this old (ms). */
  windowMs?: number;
  /** Current time in ms; injectable for tests. */
  now?: number;
}

export class History<S> {
  private past: S[] = [];
  private future: S[] = [];
  private lastKey: string | null = null;
  private lastTime = -Infinity;

  constructor(
    private current: S,
    private readonly limit = 200,
  ) {}

  get state(): S {
    return this.current;
  }

  get canUndo(): boolean {
    return this.past.length > 0;
  }

  get canRedo(): boolean {
    return this.future.length > 0;
  }

  /** Records `next` as a new state (or merges it into the last one, see HistoryOptions). */
  push(next: S, options: HistoryOptions = {}): void {
    const now = options.now ?? Date.now();
    const key = options.coalesce ?? null;
    const merge =
      key !== null &&
      key === this.lastKey &&
      (options.windowMs === undefined || now - this.lastTime <= options.windowMs);
    if (!merge) {
      this.past.push(this.current);
      if (this.past.length > this.limit) this.past.shift();
    }
    this.current = next;
    this.future = [];
    this.lastKey = key;
    this.lastTime = now;
  }

  /** Replaces the current state without an undo step (e.g. an animation frame). */
  replace(next: S): void {
    this.current = next;
  }

  /** Starts afresh from `state`, forgetting every undo step (e.g. a new lesson). */
  reset(state: S): void {
    this.current = state;
    this.past = [];
    this.future = [];
    this.lastKey = null;
  }

  undo(): S {
    const previous = this.past.pop();
    if (previous !== undefined) {
      this.future.push(this.current);
      this.current = previous;
    }
    this.lastKey = null;
    return this.current;
  }

  redo(): S {
    const next = this.future.pop();
    if (next !== undefined) {
      this.past.push(this.current);
      this.current = next;
    }
    this.lastKey = null;
    return this.current;
  }
}
