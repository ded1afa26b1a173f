import { defineConfig } from '@playwright/test';
import { chromiumArgs } from './tests/chromium';

const port = 4174;

export default defineConfig({
  testDir: 'tests/e2e',
  outputDir: 'test-results',
  // Reviewed reference images, committed: one per lesson, scene and view.
  snapshotPathTemplate: '{testDir}/__screenshots__/{arg}{ext}',
  fullyParallel: true,
  workers: 2,
  retries: 0,
  timeout: 30_000,
  expect: { timeout: 5_000 },
  // The JSON report feeds the closing count of `npm test`.
  reporter: [['list'], ['json', { outputFile: 'reports/browser.json' }]],
  use: {
    baseURL: `http://127.0.0.1:${port}/`,
    viewport: { width: 1400, height: 850 },
    // Nothing animates while a test looks.
    reducedMotion: 'reduce',
    acceptDownloads: true,
    // The service worker copies every file of the app as it installs: work
    // for each test's fresh context that only the offline tests need (they
    // allow it again). About 0.5 s of CPU per page opened.
    serviceWorkers: 'block',
    launchOptions: {
      executablePath: process.env.CHROMIUM_PATH || '/usr/bin/chromium',
      args: chromiumArgs,
    },
  },
  // Frame-time tests run last and alone, so that they time the app and not a
  // second test sharing the two cores.
  projects: [
    { name: 'browser', testIgnore: /monkey\.spec\.ts$/ },
    {
      name: 'timing',
      testMatch: /monkey\.spec\.ts$/,
      dependencies: ['browser'],
      // One at a time: what they time is the app, not a second test.
      workers: 1,
    },
  ],
  // The production build, served as a static host would.
  webServer: {
    command: `npx vite preview --host 127.0.0.1 --port ${port} --strictPort`,
    url: `http://127.0.0.1:${port}/`,
    reuseExistingServer: false,
    timeout: 60_000,
  },
});
