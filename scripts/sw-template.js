// The offline worker, written by the build (scripts/plugins.ts fills in the
// version and the list of every file it produced). On install it stores every
// file, so each lesson opens offline after the first visit even when the
// browser's HTTP cache is cleared. A missing file gets an error, never the page.
/* global __VERSION__, __PRECACHE__ */
const VERSION = __VERSION__;
const PRECACHE = __PRECACHE__;
const CACHE = `spline-lab-${VERSION}`;

self.addEventListener('install', (event) => {
  event.waitUntil(
    caches
      .open(CACHE)
      .then((cache) => cache.addAll(PRECACHE.map((url) => new Request(url, { cache: 'reload' }))))
      .then(() => self.skipWaiting()),
  );
});

self.addEventListener('activate', (event) => {
  event.waitUntil(
    caches
      .keys()
      .then((keys) => Promise.all(keys.filter((k) => k !== CACHE).map((k) => caches.delete(k))))
      .then(() => self.clients.claim()),
  );
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  const url = new URL(request.url);
  if (request.method !== 'GET' || url.origin !== self.location.origin) return;
  if (request.mode === 'navigate') {
    // The page: fresh from the network when there is one, else the stored copy.
    event.respondWith(
      fetch(request).catch(() =>
        caches
          .match('./', { ignoreSearch: true, ignoreVary: true })
          .then((hit) => hit || caches.match('./index.html')),
      ),
    );
    return;
  }
  // Every other file is named by its content (or listed above): the stored copy is right.
  event.respondWith(
    caches
      .match(request, { ignoreSearch: true, ignoreVary: true })
      .then(
        (hit) =>
          hit ||
          fetch(request).catch(
            () => new Response('', { status: 504, statusText: 'Offline and not stored' }),
          ),
      ),
  );
});
