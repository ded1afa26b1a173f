import { defineConfig } from 'vite';
import { serviceWorker, thumbnails } from './scripts/plugins.ts';

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
        manualChunks: (id) => (id.includes('node_modules/katex') ? 'katex' : undefined),
        chunkFileNames: (chunk) => {
          const lesson = /lessons\/([a-z0-9-]+)\/lesson\.ts$/.exec(chunk.facadeModuleId ?? '');
          return lesson ? `assets/lesson-${lesson[1]}-[hash].js` : 'assets/[name]-[hash].js';
        },
      },
    },
  },
});
