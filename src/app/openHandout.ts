/**
 * Opening a lesson's handout from its link (`#/<slug>/handout?…`): the
 * lesson's code and the handout's are chunks of their own, loaded then, and
 * the page shows the lesson's pages as they print.
 */
import { h, setChildren } from './dom';
import { loadState } from './lessonState';
import type { LessonMeta } from './meta';
import type { Notices } from './notices';
import { findLesson } from './registry';
import type { Settings } from './settings';
import { withLetter } from './urlState';
import { setNotation } from '../render/notation';

/** How a handout's link ends, after the lesson's slug. */
export const HANDOUT = '/handout';

/** What opening a handout needs from the app's entry. */
export interface HandoutContext {
  main: HTMLElement;
  settings: Settings;
  notices: Notices;
  showGallery(): void;
  /** The chunks, or null when they could not be loaded or another navigation came first. */
  loadFor<T>(token: number, meta: LessonMeta, load: () => Promise<T>): Promise<T | null>;
  /** The handout's own link as last written by it, or as it opened. */
  routed(hash: string): void;
}

/** A lesson's handout: its pages as they print, from the lesson's link and the handout's options. */
export async function openHandout(
  app: HandoutContext,
  token: number,
  slug: string,
  query: string,
): Promise<void> {
  const { main, settings, notices } = app;
  const { notice } = notices;
  notices.clear();
  const meta = findLesson(slug);
  if (!meta) {
    notice(`There is no lesson called “${slug.slice(0, 60)}”. Here are all the lessons.`);
    app.showGallery();
    return;
  }
  document.title = `Handout: ${meta.title} · Spline Lab`;
  setChildren(
    main,
    h('p', { class: 'loading', role: 'status' }, `Preparing the handout of ${meta.title}…`),
  );
  const loaded = await app.loadFor(token, meta, () =>
    Promise.all([meta.load(), import('./handout/handoutPage'), import('./handout/plan')]),
  );
  if (!loaded) return;
  const [lesson, { HandoutPage }, { readOptions }] = loaded;
  setNotation(lesson.letter ?? null, settings.letter);
  const read = readOptions(
    query,
    (lesson.scenes ?? []).map((scene) => scene.id),
  );
  const state = loadState(lesson, read.lessonQuery, null);
  for (const issue of [...read.issues, ...state.issues]) notice(issue);
  document.body.classList.add('handout-mode');
  // The handout's links (its title block, its QR code, back to the lesson) keep the reader's letter.
  const lessonQuery = withLetter(settings.letter, read.lessonQuery);
  const handoutPage = new HandoutPage(meta, lesson, state, lessonQuery, read.options, {
    notice,
    replaceLink: (hash) => {
      app.routed(hash);
      history.replaceState(null, '', hash);
    },
  });
  app.routed(location.hash);
  setChildren(main, handoutPage.element);
}
