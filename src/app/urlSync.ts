/**
 * Keeps the address bar and this device's memory in step with a lesson: the
 * link is written shortly after a change (at once when a gesture ends), with
 * the views the user moved, and the same text is kept in localStorage for
 * the next visit without a link.
 */
import { storageKey } from './lessonState';

export class UrlSync {
  private timer = 0;
  private written = '';
  /**
   * The address as this page last knew it (opened from, applied, or written).
   * If the address bar now shows something else, a navigation is on its way
   * (a pasted link, back/forward): its hashchange will apply it, and writing
   * the old state over it would lose it.
   */
  private known = location.hash;

  constructor(
    private readonly slug: string,
    /** The query of the current state and views. */
    private readonly query: () => string,
    /** Called after each write (a link was just written). */
    private readonly onWrite: () => void = () => undefined,
  ) {}

  /** The shareable link of the current state. */
  link(): string {
    return `#/${this.slug}?${this.query()}`;
  }

  /** A drag is on: the link waits for its end (it would only churn meanwhile). */
  private holding = false;

  hold(): void {
    this.holding = true;
    window.clearTimeout(this.timer);
    this.timer = 0;
  }

  /** Writes the link a little later; many changes in a row write once. */
  schedule(delay = 100): void {
    if (this.holding) return;
    window.clearTimeout(this.timer);
    this.timer = window.setTimeout(() => this.write(), delay);
  }

  /** The address bar's link has been applied (the page opened it, or a hashchange did). */
  adopt(): void {
    this.known = location.hash;
  }

  write(): void {
    this.holding = false;
    window.clearTimeout(this.timer);
    this.timer = 0;
    const hash = this.link();
    if (location.hash !== this.known && location.hash !== hash) return;
    if (location.hash !== hash) history.replaceState(history.state, '', hash);
    this.known = hash;
    if (hash !== this.written) {
      this.written = hash;
      this.remember();
    }
    this.onWrite();
  }

  /** A write is waiting. */
  get pending(): boolean {
    return this.timer !== 0;
  }

  /** Keeps the state on this device, for the next visit without a link. */
  remember(): void {
    try {
      localStorage.setItem(storageKey(this.slug), this.query());
    } catch {
      // Storage unavailable: the link still carries the state.
    }
  }

  /** Stops writing to the address bar (the page is going); only remember. */
  close(): void {
    window.clearTimeout(this.timer);
    this.timer = 0;
    this.remember();
  }
}
