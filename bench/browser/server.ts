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

/** Pages served at /__bench/<name>: an idle one and one with a known cost per move. */
const CHECK_PAGES: Record<string, string> = {
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
