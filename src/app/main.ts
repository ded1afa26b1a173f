/**
 * The app's entry, loaded by index.html: the device's settings, the page's
 * frame (top bar, notices, main, announcer, help), and the route from the
 * link's hash to the gallery, a lesson or a lesson's handout. A lesson's code
 * and the lesson page's are loaded only when a lesson is opened.
 */
import '../styles.css';
import { h, setChildren } from './dom';
import { showGallery } from './galleryView';
import type { LessonPage } from './lessonPage';
import type { LessonMeta } from './meta';
import { loadState } from './lessonState';
import { liveAnnouncer, noticeList } from './notices';
import { HANDOUT, type HandoutContext, openHandout } from './openHandout';
import { findLesson } from './registry';
import { parseHash } from './router';
import { applySettings, loadSettings, saveSettings } from './settings';
import { helpDialog, openHelp } from './help';
import { watchNotation } from './notationDom';
import { takeLetter } from './urlState';
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
const notices = noticeList();
const { notice } = notices;
const { element: announcer, announce } = liveAnnouncer();
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
  notices.element,
  main,
  announcer,
  help,
);

function rerender(): void {
  theme = applySettings(settings);
  saveSettings(settings);
  topBar.pressed(settings.projector, settings.dark);
  if (page) page.refresh();
  else if (parseHash(location.hash).slug === null) showGallery(main, settings.dark);
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
    showGallery(main, settings.dark);
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
    await openHandout(handoutContext, token, slug, query);
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
  notices.clear();
  if (taken.issue) notice(taken.issue);
  setNotation(null, settings.letter);
  const meta = slug === null ? undefined : findLesson(slug);
  if (slug !== null && !meta) {
    notice(`There is no lesson called “${slug.slice(0, 60)}”. Here are all the lessons.`);
  }
  if (!meta) {
    showGallery(main, settings.dark);
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

/** The handout's own link as last written by it (an option changed): no need to build it again. */
let routedHandout: string | null = null;
const handoutContext: HandoutContext = {
  main,
  settings,
  notices,
  showGallery: () => showGallery(main, settings.dark),
  loadFor,
  routed: (hash) => {
    routedHandout = hash;
  },
};

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
