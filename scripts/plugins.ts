/**
 * Build steps of our own (Vite plugins):
 * - thumbnails: each lesson's gallery thumbnail drawn at build time by its
 *   own figure code (through Vite's module runner), served live in dev;
 * - serviceWorker: the offline worker, written with the list of every file
 *   the build produced, so it precaches them all on the first visit.
 */
import { createHash } from 'node:crypto';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { type Plugin, createServer } from 'vite';

interface ThumbnailModule {
  renderThumbnails(): Promise<Record<string, string>>;
}

const THUMBNAILS = '/src/app/thumbnails.ts';

export function thumbnails(): Plugin {
  let root = process.cwd();
  return {
    name: 'spline-lab:thumbnails',
    configResolved(config) {
      root = config.root;
    },
    configureServer(server) {
      server.middlewares.use(async (req, res, next) => {
        const match = /\/thumbnails\/([a-z0-9-]+\.svg)$/.exec(req.url ?? '');
        if (!match) return next();
        try {
          const module = (await server.ssrLoadModule(THUMBNAILS)) as ThumbnailModule;
          const svg = (await module.renderThumbnails())[match[1]];
          if (!svg) return next();
          res.setHeader('Content-Type', 'image/svg+xml');
          res.end(svg);
        } catch (error) {
          next(error);
        }
      });
    },
    async generateBundle() {
      // A server of our own, for its module loader only (the lessons load one another lazily).
      const server = await createServer({
        root,
        configFile: false,
        logLevel: 'error',
        appType: 'custom',
        server: { middlewareMode: true, hmr: false, ws: false },
      });
      try {
        const module = (await server.ssrLoadModule(THUMBNAILS)) as ThumbnailModule;
        for (const [name, svg] of Object.entries(await module.renderThumbnails()))
          this.emitFile({ type: 'asset', fileName: `thumbnails/${name}`, source: svg });
      } finally {
        await server.close();
      }
    },
  };
}

function listFiles(dir: string): string[] {
  let files: string[] = [];
  try {
    for (const name of readdirSync(dir)) {
      const path = join(dir, name);
      files = statSync(path).isDirectory() ? [...files, ...listFiles(path)] : [...files, path];
    }
  } catch {
    // No public folder: nothing to add.
  }
  return files;
}

export function serviceWorker(): Plugin {
  let publicDir = '';
  return {
    name: 'spline-lab:service-worker',
    apply: 'build',
    enforce: 'post',
    configResolved(config) {
      publicDir = config.publicDir;
    },
    generateBundle(_options, bundle) {
      const built = Object.keys(bundle);
      const copied = listFiles(publicDir).map((path) =>
        relative(publicDir, path).split('\\').join('/'),
      );
      const files = [...new Set([...built, ...copied])].filter((f) => f !== 'sw.js').sort();
      // The version changes whenever any file's name or content changes, so the
      // browser installs the new worker and its fresh cache.
      const hash = createHash('sha256');
      for (const name of built) {
        const item = bundle[name];
        hash.update(name);
        hash.update(item.type === 'chunk' ? item.code : item.source);
      }
      const template = readFileSync(new URL('./sw-template.js', import.meta.url), 'utf8');
      const source = template
        .replace('= __VERSION__;', `= ${JSON.stringify(hash.digest('hex').slice(0, 12))};`)
        .replace('= __PRECACHE__;', `= ${JSON.stringify(['./', ...files.map((f) => `./${f}`)])};`);
      this.emitFile({ type: 'asset', fileName: 'sw.js', source });
    },
  };
}
