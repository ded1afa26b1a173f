import { defineConfig } from 'vite';

// base './' so that dist/ works from any static host and from a sub-path.
export default defineConfig({
  base: './',
  build: {
    target: 'es2022',
    outDir: 'dist',
    assetsInlineLimit: 0,
  },
});
