import { defineConfig } from 'vite';
import { serviceWorker, thumbnails } from './scripts/plugins.ts';

type ModuleInfo = { isEntry: boolean; importers: readonly string[] } | null;

/** Whether the entry (the gallery's code) imports `id`, directly or through other modules. */
function inEntryGraph(
  id: string,
  info: (id: string) => ModuleInfo,
  seen = new Set<string>(),
): boolean {
  // The page (index.html) is the entry; main.ts is imported by it.
  if (id.endsWith('.html')) return true;
  const module = info(id);
  if (!module) return false;
  if (module.isEntry) return true;
  seen.add(id);
  return module.importers.some((by) => !seen.has(by) && inEntryGraph(by, info, seen));
}

// base './' so that dist/ works from any static host and from a sub-path.
export default defineConfig({
  base: './',
  plugins: [thumbnails(), serviceWorker()],
  build: {
    target: 'es2022',
    outDir: 'dist',
    assetsInlineLimit: 0,
    rollupOptions: {
      output: {
        // Each lesson's chunk is named after it (lesson-road-….js), for people and the bench.
        // KaTeX is its own chunk, shared by every lesson and named for what it is.
        // The lesson page's own code (app, render, interact, math) is one
        // chunk too: split by what each lesson happened to import, it was 20
        // small files fetched at once, over six connections, before a lesson
        // could draw (200–480 ms of a load). What the gallery loads stays out.
        manualChunks: (id, { getModuleInfo }) => {
          if (id.includes('node_modules/katex')) return 'katex';
          if (!/\/src\/(app|render|interact|math)\//.test(id) || id.endsWith('/main.ts'))
            return undefined;
          // The gallery's modules are named too: a chunk takes in its modules'
          // imports, and the gallery must not load the shell to get them.
          return inEntryGraph(id, getModuleInfo) ? 'gallery' : 'shell';
        },
        chunkFileNames: (chunk) => {
          const lesson = /lessons\/([a-z0-9-]+)\/lesson\.ts$/.exec(chunk.facadeModuleId ?? '');
          return lesson ? `assets/lesson-${lesson[1]}-[hash].js` : 'assets/[name]-[hash].js';
        },
      },
    },
  },
});
