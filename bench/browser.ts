// `npm run bench`, browser part: builds the app into a temp folder, serves it
// on 127.0.0.1 and measures it in headless Chromium at 1920×1080, device scale
// 2: main-thread time per frame while dragging in every lesson the gallery
// links to, the JS it fetches, and how long a lesson takes to show its first
// figure. Prints figures only; nothing here is asserted. Exits non-zero only
// when it cannot run at all.
import type { Browser } from '@playwright/test';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { checkMethod, referenceDrag } from './browser/check';
import type { DragLimits } from './browser/drag';
import { dragLesson, dragPreset, type DragRow, type PresetDrag } from './browser/lessonDrags';
import { lessonScripts, loadTimes, openGallery, type ScriptFile } from './browser/load';
import { launchBrowser } from './browser/page';
import { type LessonLoad, printReport } from './browser/report';
import { serveStatic } from './browser/server';
import { quantile } from './browser/trace';
import { type HandoutRow, handoutTimes, printHandouts } from './browser/handout';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
/**
 * 300 frames (10 s at two 60 Hz frames a move), but at most BENCH_DRAG_SECONDS
 * (default 11) a drag, so that a slow app measures fewer frames rather than
 * taking the whole run past five minutes.
 */
const LIMITS: DragLimits = { frames: 300, seconds: Number(process.env.BENCH_DRAG_SECONDS) || 11 };
/** The method check needs fewer frames: its pages do the same thing every frame. */
const CHECK_LIMITS: DragLimits = { frames: 100, seconds: 6 };
const LOAD_RUNS = 10;
const PRESETS: readonly PresetDrag[] = [
  { lesson: 'road', button: 'Valley: 500 villages', pointKind: 'village' },
];

/** Seconds each part of the run took, printed at the end. */
const phases: [string, number][] = [];

/** Runs one part of the benchmark and notes how long it took. */
async function timed<T>(name: string, run: () => Promise<T> | T): Promise<T> {
  const start = performance.now();
  try {
    return await run();
  } finally {
    phases.push([name, (performance.now() - start) / 1000]);
  }
}

/** Progress for a person watching; the figures go to stdout. */
function progress(message: string): void {
  if (process.stderr.isTTY) process.stderr.write(`… ${message}\n`);
}

function build(outDir: string): void {
  const result = spawnSync(
    'npx',
    ['vite', 'build', '--outDir', outDir, '--emptyOutDir', '--logLevel', 'warn'],
    { cwd: ROOT, stdio: ['ignore', 'inherit', 'inherit'] },
  );
  if (result.status !== 0) throw new Error(`vite build failed (exit ${result.status})`);
}

/** Every .js file of the build, gzipped, to name the ones the gallery did not fetch. */
function builtScripts(outDir: string): ScriptFile[] {
  return readdirSync(outDir, { recursive: true, encoding: 'utf8' })
    .filter((file) => file.endsWith('.js'))
    .map((file) => {
      const body = readFileSync(join(outDir, file));
      return {
        path: `/${file.split(sep).join('/')}`,
        bytes: body.length,
        gzip: gzipSync(body).length,
      };
    });
}

/** Runs one measurement; a failure becomes a line of the table instead of ending the run. */
async function orNote(lesson: string, control: string, run: () => Promise<DragRow[]>) {
  try {
    return await run();
  } catch (error) {
    const message = (error instanceof Error ? error.message : String(error)).split('\n')[0];
    return [{ lesson, control, note: `failed: ${message}` }];
  }
}

/**
 * Every lesson's drags, each beside the reference page measured just before and
 * just after them, pooled: one reference run of 100 frames put its p95 anywhere
 * from 14.2 to 20.7 ms within a run, and the machine drifting during a lesson's
 * drags moved the ratio with it. Bracketed, the lesson's frames sit between the
 * two halves of the figure they are divided by.
 */
async function measureDrags(browser: Browser, base: string, slugs: readonly string[]) {
  const rows: DragRow[] = [];
  const reference = () => referenceDrag(browser, base, CHECK_LIMITS);
  let before = slugs.length > 0 ? await reference() : null;
  for (const slug of slugs) {
    progress(`dragging in ${slug}, then the reference page`);
    const lessonRows = await orNote(slug, 'point', () => dragLesson(browser, base, slug, LIMITS));
    for (const preset of PRESETS.filter((p) => p.lesson === slug)) {
      progress(`${slug}: preset ${preset.button}`);
      lessonRows.push(
        ...(await orNote(slug, preset.button, () => dragPreset(browser, base, preset, LIMITS))),
      );
    }
    const after = await reference();
    const referenceP95 = quantile([...before!.perFrame, ...after.perFrame], 0.95);
    rows.push(...lessonRows.map((row) => ({ ...row, referenceP95 })));
    before = after;
  }
  for (const preset of PRESETS.filter((p) => !slugs.includes(p.lesson)))
    rows.push({ lesson: preset.lesson, control: preset.button, note: 'lesson not in the gallery' });
  return rows;
}

async function measureLoads(browser: Browser, base: string, slugs: readonly string[]) {
  // Does the app set its first-draw mark? Ask the first lesson, waiting up to 3 s for it.
  const probe = slugs.length > 0 ? await loadTimes(browser, base, slugs[0], 1, 3000) : null;
  const markWaitMs = probe && probe.byMark > 0 ? 2000 : 0;
  const rows: LessonLoad[] = [];
  for (const slug of slugs) {
    progress(`loading ${slug} ${LOAD_RUNS} times`);
    let extra: ScriptFile[] | null = null;
    try {
      extra = await lessonScripts(browser, base, slug);
    } catch {
      extra = null;
    }
    const load = await loadTimes(browser, base, slug, LOAD_RUNS, markWaitMs);
    rows.push({ lesson: slug, extra, load });
  }
  return { rows, markSeen: markWaitMs > 0 };
}

async function measure(browser: Browser, base: string, outDir: string): Promise<void> {
  progress('checking the per-frame measurement on pages of our own');
  const checks = await timed('method check', () => checkMethod(browser, base, CHECK_LIMITS));
  progress('opening the gallery');
  const gallery = await timed('gallery', () => openGallery(browser, base));
  if (gallery.slugs.length === 0)
    console.log('The gallery links to no lesson (a.card[data-slug]).');
  const drags = await timed('drags', () => measureDrags(browser, base, gallery.slugs));
  const loads = await timed('JS and loads', () => measureLoads(browser, base, gallery.slugs));
  const handouts = await timed('handouts', async () => {
    const rows: HandoutRow[] = [];
    for (const slug of gallery.slugs) {
      progress(`making the handout of ${slug}`);
      rows.push(await handoutTimes(browser, base, slug));
    }
    return rows;
  });
  const fetched = new Set(gallery.scripts.map((f) => f.path));
  const unfetched = builtScripts(outDir).filter((f) => !fetched.has(f.path));

  printReport({
    browserVersion: browser.version(),
    limits: LIMITS,
    checkFrames: CHECK_LIMITS.frames,
    checks,
    drags,
    gallery: gallery.scripts,
    unfetched,
    loads: loads.rows,
    loadRuns: LOAD_RUNS,
    markSeen: loads.markSeen,
  });
  printHandouts(handouts);
}

async function main(): Promise<void> {
  const started = performance.now();
  const outDir = mkdtempSync(join(tmpdir(), 'spline-lab-bench-'));
  try {
    progress(`building into ${outDir}`);
    await timed('build', () => build(outDir));
    const server = await serveStatic(outDir);
    try {
      const browser = await launchBrowser();
      try {
        await measure(browser, server.url, outDir);
      } finally {
        await browser.close();
      }
    } finally {
      await server.close();
    }
  } finally {
    rmSync(outDir, { recursive: true, force: true });
  }
  const total = (performance.now() - started) / 1000;
  const parts = phases.map(([name, seconds]) => `${name} ${seconds.toFixed(0)} s`).join(', ');
  console.log(`\nBrowser benchmark took ${total.toFixed(0)} s (${parts}).`);
}

main().catch((error: unknown) => {
  console.error(
    `The browser benchmark could not run: ${error instanceof Error ? error.stack : error}`,
  );
  process.exitCode = 1;
});
