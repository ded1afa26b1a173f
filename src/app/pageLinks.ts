/**
 * A lesson page's links: the address bar kept in step with the state and the
 * views the user moved, a link typed in or reached by back/forward applied,
 * and the links the page hands out (Copy link, the handout).
 */
import type { FigureView } from './figureView';
import type { AnyLesson } from './lesson';
import { LessonStore, type Loaded } from './lessonState';
import type { PracticeHost } from './practiceHost';
import { parseHash } from './router';
import { UrlSync } from './urlSync';
import { withLetter, withPractice } from './urlState';
import { chosenLetter } from '../render/notation';

export interface LinkHost<S, M> {
  readonly lesson: AnyLesson;
  readonly store: LessonStore<S>;
  readonly figures: readonly FigureView<S, M>[];
  /** The lesson's exercises, if it has any: an exercise's link is theirs. */
  practice(): PracticeHost<S> | undefined;
  /** A link names its scene: the clicker's walk starts there. */
  restart(scene: number): void;
  notice(message: string): void;
}

export class PageLinks<S, M> {
  readonly url: UrlSync;

  constructor(private readonly host: LinkHost<S, M>) {
    this.url = new UrlSync(host.lesson.slug, () => {
      // An exercise's link: its id and seed, then the figure as the student has it now.
      // The reader's letter for the parameter goes first, when it is not the usual t.
      return withLetter(
        chosenLetter(),
        withPractice(host.practice()?.link() ?? null, host.store.query(this.views())),
      );
    });
  }

  /** The views the user moved, by figure id, for the link. */
  private views(): Record<string, string> {
    const views: Record<string, string> = {};
    for (const figure of this.host.figures) {
      const text = figure.viewText();
      if (text !== null) views[figure.spec.id] = text;
    }
    return views;
  }

  /** Gives each figure the view its link carries (or fits it), saying which could not be read. */
  applyViews(views: Readonly<Record<string, string>>): void {
    for (const figure of this.host.figures) {
      const text = views[figure.spec.id] ?? null;
      if (!figure.applyView(text))
        this.host.notice(
          `Ignored from the link: the view of “${figure.spec.title}” could not be read; it was fitted to the figure.`,
        );
    }
  }

  /** The address bar names this lesson without a state: it shows the current one again. */
  keepState(): void {
    this.url.adopt();
    this.url.write();
  }

  /** Applies a state typed into the address bar or reached by back/forward. */
  applyQuery(loaded: Loaded<S>): void {
    const { lesson, store } = this.host;
    this.url.adopt();
    if (this.host.practice()?.applyLink(loaded)) return;
    this.host.restart(loaded.scene);
    for (const issue of loaded.issues) this.host.notice(`Ignored from the link: ${issue}.`);
    this.applyViews(loaded.views);
    const same = store.query() === new LessonStore<S>(lesson, loaded.state).query();
    if (same) {
      // Nothing changed, but the address bar must show the state in force.
      this.url.write();
      return;
    }
    store.set(loaded.state);
  }

  /** The handout of the lesson as it is now (its link carries the state and the views). */
  openHandout(): void {
    this.url.write();
    const { slug, query } = parseHash(this.url.link());
    location.hash = `#/${slug}/handout${query ? `?${query}` : ''}`;
  }

  async copyLink(): Promise<void> {
    this.url.write();
    const url = location.href;
    try {
      await navigator.clipboard.writeText(url);
      this.host.notice('Link copied. It opens this lesson exactly as it is now.');
    } catch {
      this.host.notice(`Copy this link: ${url}`);
    }
  }
}
