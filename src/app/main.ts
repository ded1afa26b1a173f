import '../styles.css';
import { h, setChildren } from './dom';
import { buildGallery } from './gallery';
import type { LessonPage } from './lessonPage';
import type { LessonMeta } from './meta';
import { loadState } from './lessonState';
import { findLesson, lessons } from './registry';
import { parseHash } from './router';
import { applySettings, loadSettings, saveSettings } from './settings';
import { helpDialog, openHelp } from './help';
import { watchNotation } from './notationDom';
import { takeLetter, withLetter } from './urlState';
import { type Letter, setNotation } from '../render/notation';
import { listenForKeys } from './appKeys';
import { TopBar } from './topBar';

const settings = loadSettings();
let theme = applySettings(settings);
let page: LessonPage<unknown, unknown> | null = null;
/** The letter the open page was built with: another letter builds it again. */
let pageLetter: Letter = settings.letter;
/** The latest navigation: a lesson that finishes loading after another was asked for is dropped. */
let routeToken = 0;
/** The navigation in progress (a lesson's code may still be loading). */
let routing: Promise<void> = Promise.resolve();

const main = h('main', { id: 'main', tabindex: '-1' });
const notices = h('div', { class: 'notices', role: 'status', 'aria-live': 'polite' });
const announcer = h('div', {
  class: 'visually-hidden',
  'aria-live': 'polite',
  'data-announcer': '',
});
const help = helpDialog();

const topBar = new TopBar(settings, {
  projector: () => toggleProjector(),
  dark: () => toggleDark(),
  letter: (letter) => chooseLetter(letter),
  fullscreen: () => toggleFullscreen(),
  help: () => openHelp(help),
});
document.body.append(
  h(
    'a',
    {
      class: 'skip',
      href: '#main',
      onclick: (e: Event) => {
        e.preventDefault();
        main.focus();
      },
    },
    'Skip to content',
  ),
  topBar.element,
  notices,
  main,
  announcer,
  help,
);

export function notice(message: string): void {
  const close = h(
    'button',
    { type: 'button', class: 'notice-close', 'aria-label': 'Dismiss notice' },
    '×',
  );
  const item = h('div', { class: 'notice' }, h('span', {}, message), close);
  close.addEventListener('click', () => item.remove());
  notices.append(item);
  while (notices.childElementCount > 4) notices.firstElementChild?.remove();
}

function announce(message: string): void {
  // Written even when the words are the same: a live region then says them again.
  // eslint-disable-next-line no-restricted-syntax
  announcer.textContent = message;
}

function rerender(): void {
  theme = applySettings(settings);
  saveSettings(settings);
  topBar.pressed(settings.projector, settings.dark);
  if (page) page.refresh();
  else if (parseHash(location.hash).slug === null) showGallery();
}

/** The reader's letter for the curve parameter: kept on the device, in the link, and the page says it. */
function chooseLetter(letter: Letter): void {
  if (letter === settings.letter) return;
  settings.letter = letter;
  saveSettings(settings);
  topBar.letter(letter);
  setNotation(page?.lesson.letter ?? null, letter);
  // The link takes the letter now; the page is built again in it.
  page?.writeUrl();
  routing = route();
}

function toggleProjector(): void {
  settings.projector = !settings.projector;
  rerender();
}

function toggleDark(): void {
  settings.dark = !settings.dark;
  rerender();
}

function toggleFullscreen(): void {
  if (document.fullscreenElement) void document.exitFullscreen();
  else
    void document.documentElement
      .requestFullscreen?.()
      .catch(() => notice('This browser did not allow full screen here.'));
}

function showGallery(): void {
  document.title = 'Spline Lab';
  setChildren(main, buildGallery(lessons, settings.dark));
}

/**
 * A lesson's code and the chunks its page needs, or null when they could not
 * be loaded (said in a notice, the gallery shown) or another navigation came first.
 */
async function loadFor<T>(
  token: number,
  meta: LessonMeta,
  load: () => Promise<T>,
): Promise<T | null> {
  try {
    const value = await load();
    return token === routeToken ? value : null;
  } catch {
    if (token !== routeToken) return null;
    notice(`${meta.title} could not be loaded. Check the connection and open it again.`);
    showGallery();
    return null;
  }
}

async function route(): Promise<void> {
  const token = ++routeToken;
  const { slug: path, query: linkQuery } = parseHash(location.hash);
  // A link's letter is the reader's from now on (a lecturer's link opens in the lecturer's letter).
  const taken = takeLetter(linkQuery);
  const query = taken.rest;
  if (taken.letter && taken.letter !== settings.letter) {
    settings.letter = taken.letter;
    saveSettings(settings);
    topBar.letter(taken.letter);
  }
  const handout = path?.endsWith(HANDOUT) ?? false;
  const slug = handout && path ? path.slice(0, -HANDOUT.length) : path;
  if (handout && slug !== null) {
    if (routedHandout === location.hash) return;
    page?.destroy();
    page = null;
    await openHandout(token, slug, query);
    return;
  }
  routedHandout = null;
  document.body.classList.remove('handout-mode');
  if (slug !== null && page && page.lesson.slug === slug && pageLetter === settings.letter) {
    // A bare link to the open lesson (“#/de-casteljau”) keeps what is on
    // screen, as opening it afresh restores the last state; a link with a
    // state (typed into the address bar, or back/forward) applies it.
    if (taken.issue) notice(taken.issue);
    if (query === '') page.links.keepState();
    else page.links.applyQuery(loadState(page.lesson, query, null));
    return;
  }
  page?.destroy();
  page = null;
  notices.replaceChildren();
  if (taken.issue) notice(taken.issue);
  setNotation(null, settings.letter);
  const meta = slug === null ? undefined : findLesson(slug);
  if (slug !== null && !meta) {
    notice(`There is no lesson called “${slug.slice(0, 60)}”. Here are all the lessons.`);
  }
  if (!meta) {
    showGallery();
    return;
  }
  document.title = `${meta.title} · Spline Lab`;
  setChildren(main, h('p', { class: 'loading', role: 'status' }, `Opening ${meta.title}…`));
  // The lesson's own code and the page shell are chunks of their own, loaded now.
  const loaded = await loadFor(token, meta, () =>
    Promise.all([meta.load(), import('./lessonPage')]),
  );
  if (!loaded) return;
  const [lesson, { LessonPage }] = loaded;
  let storage: Storage | null = null;
  try {
    storage = localStorage;
  } catch {
    storage = null;
  }
  setNotation(lesson.letter ?? null, settings.letter);
  pageLetter = settings.letter;
  page = new LessonPage(meta, lesson, loadState(lesson, query, storage), {
    theme: () => theme,
    notice,
    announce,
    togglePresenter: () => toggleProjector(),
  });
  setChildren(main, page.element);
}

const HANDOUT = '/handout';
/** The handout's own link as last written by it (an option changed): no need to build it again. */
let routedHandout: string | null = null;

/** A lesson's handout: its pages as they print, from the lesson's link and the handout's options. */
async function openHandout(token: number, slug: string, query: string): Promise<void> {
  notices.replaceChildren();
  const meta = findLesson(slug);
  if (!meta) {
    notice(`There is no lesson called “${slug.slice(0, 60)}”. Here are all the lessons.`);
    showGallery();
    return;
  }
  document.title = `Handout: ${meta.title} · Spline Lab`;
  setChildren(
    main,
    h('p', { class: 'loading', role: 'status' }, `Preparing the handout of ${meta.title}…`),
  );
  const loaded = await loadFor(token, meta, () =>
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
      routedHandout = hash;
      history.replaceState(null, '', hash);
    },
  });
  routedHandout = location.hash;
  setChildren(main, handoutPage.element);
}

watchNotation(main);

window.addEventListener('hashchange', () => {
  routing = route();
});
listenForKeys(() => page, {
  presenter: () => toggleProjector(),
  dark: () => toggleDark(),
  fullscreen: () => toggleFullscreen(),
  help: () => openHelp(help),
  gallery: () => {
    location.hash = '#/';
  },
  helpOpen: () => help.open,
});
window.addEventListener('pagehide', () => page?.writeUrl());

// For tests and tools driving the page: resolves once a change has settled
// (state final, frame drawn, panel updated, link written).
Object.defineProperty(window, 'splineLab', {
  value: Object.freeze({
    settled: async () => {
      await routing;
      await page?.settled();
    },
    labels: () => page?.labelBoxes() ?? [],
    probe: (figure: string, point: number[] | null, id: string | null) =>
      page?.probe(figure, point, id) ?? null,
  }),
});
routing = route();

if (import.meta.env.PROD && 'serviceWorker' in navigator) {
  // Offline once loaded: the worker keeps a copy of every file the app fetched.
  navigator.serviceWorker.register('./sw.js').catch(() => undefined);
}
