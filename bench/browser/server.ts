// A tiny static server for the benchmark's own build, on 127.0.0.1 at a free
// port, plus two pages of its own that check the per-frame measurement.
import { readFile } from 'node:fs/promises';
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { extname, join, normalize } from 'node:path';

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.svg': 'image/svg+xml',
  '.json': 'application/json',
  '.png': 'image/png',
  '.woff2': 'font/woff2',
  '.woff': 'font/woff',
  '.ttf': 'font/ttf',
};

/** The busy page's pointermove listener spins this long, so its frames have a known cost. */
export const BUSY_MS = 5;

/** How many segments the reference page strokes each frame. */
export const REFERENCE_SEGMENTS = 2000;

/**
 * The reference a drag frame is compared with: a full-window canvas at the
 * device's pixel ratio that, on every pointer move, clears itself and strokes
 * one path of REFERENCE_SEGMENTS segments (a curve that follows the pointer),
 * in the next animation frame, as the app draws.
 */
const REFERENCE_PAGE = `<!doctype html><title>reference</title>
<body style="margin:0;height:100vh;overflow:hidden"><canvas style="display:block;width:100vw;height:100vh"></canvas><script>
const canvas = document.querySelector('canvas');
const dpr = devicePixelRatio || 1;
canvas.width = Math.round(innerWidth * dpr);
canvas.height = Math.round(innerHeight * dpr);
const ctx = canvas.getContext('2d');
let at = [innerWidth / 2, innerHeight / 2];
let pending = false;
function draw() {
  pending = false;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, innerWidth, innerHeight);
  ctx.beginPath();
  for (let i = 0; i <= ${REFERENCE_SEGMENTS}; i++) {
    const s = i / ${REFERENCE_SEGMENTS};
    const x = innerWidth * (0.05 + 0.9 * s);
    const y = at[1] + 0.3 * innerHeight * Math.sin(12 * s + at[0] / 100) * (1 - s);
    if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
  }
  ctx.lineWidth = 3;
  ctx.strokeStyle = '#0050a0';
  ctx.stroke();
}
addEventListener('pointermove', (e) => {
  at = [e.clientX, e.clientY];
  if (!pending) { pending = true; requestAnimationFrame(draw); }
});
draw();
</script></body>`;

/** Pages served at /__bench/<name>: an idle one, one with a known cost per move, the reference. */
const CHECK_PAGES: Record<string, string> = {
  'reference.html': REFERENCE_PAGE,
  'idle.html': '<!doctype html><title>idle</title><body style="margin:0;height:100vh"></body>',
  'busy.html': `<!doctype html><title>busy</title><body style="margin:0;height:100vh"><script>
addEventListener('pointermove', () => { const end = performance.now() + ${BUSY_MS}; while (performance.now() < end); });
</script></body>`,
};

export interface StaticServer {
  /** Base address ending in "/". */
  readonly url: string;
  close(): Promise<void>;
}

export async function serveStatic(root: string): Promise<StaticServer> {
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://x').pathname);
    const check = path.startsWith('/__bench/') ? CHECK_PAGES[path.slice('/__bench/'.length)] : '';
    if (check) {
      response.writeHead(200, { 'content-type': TYPES['.html'], 'cache-control': 'no-store' });
      response.end(check);
      return;
    }
    const file = join(root, normalize(path.endsWith('/') ? `${path}index.html` : path));
    if (!file.startsWith(root)) {
      response.writeHead(403).end();
      return;
    }
    readFile(file).then(
      (body) => {
        response.writeHead(200, {
          'content-type': TYPES[extname(file)] ?? 'application/octet-stream',
          'cache-control': 'no-store',
        });
        response.end(body);
      },
      () => response.writeHead(404).end(),
    );
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  return { url: `http://127.0.0.1:${port}/`, close: () => closeServer(server) };
}

function closeServer(server: Server): Promise<void> {
  server.closeAllConnections();
  return new Promise((resolve) => server.close(() => resolve()));
}
