// Printing: Markdown tables a reader can paste, figures with their budgets.
import type { MethodCheck } from './check';
import { type DragLimits, type DragResult, FRAME_MEASURE } from './drag';
import type { DragRow } from './lessonDrags';
import type { LoadTimes, ScriptFile } from './load';
import { FALLBACK_METHOD, FIRST_DRAW_MARK } from './page';
import { BUSY_MS, REFERENCE_SEGMENTS } from './server';
import { quantile } from './trace';

export const BUDGET = { frameP95Ms: 4, galleryKb: 60, loadMs: 500 };

export function printTable(header: readonly string[], rows: readonly (readonly string[])[]): void {
  const widths = header.map((title, c) =>
    Math.max(title.length, ...rows.map((row) => (row[c] ?? '').length)),
  );
  const line = (cells: readonly string[]) =>
    `| ${widths.map((w, c) => (cells[c] ?? '').padEnd(w)).join(' | ')} |`;
  console.log(line(header));
  console.log(`|${widths.map((w) => '-'.repeat(w + 2)).join('|')}|`);
  for (const row of rows) console.log(line(row));
}

export function ms(value: number): string {
  if (!Number.isFinite(value)) return '—';
  return value >= 100 ? value.toFixed(0) : value >= 10 ? value.toFixed(1) : value.toFixed(2);
}

/** Kilobytes of 1000 bytes, as `vite build` prints them. */
export function kb(bytes: number): string {
  return `${(bytes / 1000).toFixed(1)} KB`;
}

const frameColumns = (p95: string) => [
  'p50 (ms)',
  p95,
  'CPU p50 / p95 (ms)',
  'app p50 / p95 (ms)',
  'frames measured',
];

/** p50, p95, CPU p50 / p95, frames measured (and any moves the page merged). */
function frameFigures(result: DragResult): string[] {
  const merged =
    result.dispatched < result.moves ? ` (${result.moves - result.dispatched} moves merged)` : '';
  const cpu = result.cpuPerFrame;
  return [
    ms(quantile(result.perFrame, 0.5)),
    ms(quantile(result.perFrame, 0.95)),
    `${ms(quantile(cpu, 0.5))} / ${ms(quantile(cpu, 0.95))}`,
    result.appPerFrame.length
      ? `${ms(quantile(result.appPerFrame, 0.5))} / ${ms(quantile(result.appPerFrame, 0.95))}`
      : '—',
    `${result.perFrame.length}${merged}`,
  ];
}

export function printChecks(checks: readonly MethodCheck[]): void {
  printTable(
    ['check page', 'expected', ...frameColumns('p95 (ms)')],
    checks.map((c) => [c.page, c.expected, ...frameFigures(c.result)]),
  );
}

/**
 * The drags, each with its p95 as a multiple of the reference page's p95
 * measured just before and after its lesson's drags (else `referenceP95`): target ≤ 1.0×.
 */
export function printDrags(rows: readonly DragRow[], referenceP95: number): void {
  printTable(
    [
      'lesson',
      'preset / control',
      ...frameColumns(`p95 (ms), budget ≤ ${BUDGET.frameP95Ms}`),
      'reference p95 beside it (ms)',
      'p95 ÷ reference, target ≤ 1.0×',
      'state changed (moves)',
    ],
    rows.map((row) =>
      row.result
        ? [
            row.lesson,
            row.control,
            ...frameFigures(row.result),
            ms(row.referenceP95 ?? referenceP95),
            `${(quantile(row.result.perFrame, 0.95) / (row.referenceP95 ?? referenceP95)).toFixed(2)}×`,
            `${row.result.changed}/${row.result.moves}`,
          ]
        : [row.lesson, row.control, '—', '—', '—', '0', '—', '—', row.note ?? ''],
    ),
  );
}

export function sumGzip(files: readonly ScriptFile[]): number {
  return files.reduce((sum, f) => sum + f.gzip, 0);
}

export function printGallery(files: readonly ScriptFile[], unfetched: readonly ScriptFile[]): void {
  const gzip = sumGzip(files);
  const raw = files.reduce((sum, f) => sum + f.bytes, 0);
  const verdict = gzip <= BUDGET.galleryKb * 1000 ? 'within budget' : 'over budget';
  console.log(
    `Gallery #/ fresh: ${kb(gzip)} gzip (${kb(raw)} as served) in ${files.length} .js file(s), budget ≤ ${BUDGET.galleryKb} KB gzip: ${verdict}`,
  );
  for (const f of files) console.log(`  ${f.path}: ${kb(f.gzip)} gzip, ${kb(f.bytes)} as served`);
  for (const f of unfetched)
    console.log(`  not fetched by the gallery: ${f.path}, ${kb(f.gzip)} gzip (not counted)`);
}

export interface LessonLoad {
  readonly lesson: string;
  readonly extra: readonly ScriptFile[] | null;
  readonly load: LoadTimes;
  readonly note?: string;
}

export function printLoads(rows: readonly LessonLoad[], runs: number): void {
  printTable(
    [
      'lesson',
      'extra JS gzip (opened from the gallery)',
      `load median of ${runs} (ms), budget ≤ ${BUDGET.loadMs}`,
      'min (ms)',
      'max (ms)',
      'measured by',
    ],
    rows.map(({ lesson, extra, load, note }) => [
      lesson,
      extra === null ? '—' : `${kb(sumGzip(extra))} in ${extra.length} file(s)`,
      ms(quantile(load.times, 0.5)),
      ms(Math.min(...load.times)),
      ms(Math.max(...load.times)),
      note ?? method(load),
    ]),
  );
}

function method(load: LoadTimes): string {
  if (load.times.length === 0) return 'no figure drawn';
  if (load.byMark === load.times.length) return 'app mark';
  if (load.byMark === 0) return 'watcher';
  return `app mark ${load.byMark}, watcher ${load.times.length - load.byMark}`;
}

export interface Report {
  readonly browserVersion: string;
  readonly limits: DragLimits;
  /** Frames of each check page's drag, and of the reference drag beside each lesson. */
  readonly checkFrames: number;
  readonly checks: readonly MethodCheck[];
  readonly drags: readonly DragRow[];
  readonly gallery: readonly ScriptFile[];
  readonly unfetched: readonly ScriptFile[];
  readonly loads: readonly LessonLoad[];
  readonly loadRuns: number;
  readonly markSeen: boolean;
}

/** Everything, in the order a reader wants it: how it was measured, then the figures. */
export function printReport(report: Report): void {
  const { limits } = report;
  console.log(
    `Spline Lab browser benchmark — Chromium ${report.browserVersion} headless (--disable-gpu), ` +
      `1920×1080 at deviceScaleFactor 2, production build on 127.0.0.1\n`,
  );
  console.log(
    `Drags: real mouse input, one move per animation frame (move, then wait for the page's next ` +
      `requestAnimationFrame), ${limits.frames} frames or ${limits.seconds} s per drag, whichever ends ` +
      `first; a point goes round a 40 px circle, a slider's thumb to and fro at about 1.25 steps a frame. ` +
      `Main-thread time per frame = sum of the renderer main thread's top-level RunTask durations ` +
      `between consecutive moves (Chromium trace).\n`,
  );
  console.log('Method check (same harness, pages of our own):');
  printChecks(report.checks);
  const [idle, busy] = report.checks.map((c) => quantile(c.result.perFrame, 0.5));
  const reference = quantile(report.checks[2].result.perFrame, 0.95);
  console.log(
    `busy − idle at the median: ${ms(busy - idle)} ms (expected ${BUSY_MS}). The idle page's figure ` +
      `is the harness's own main-thread cost (routing the mouse move, the frame it waits for, the ` +
      `evaluate, tracing); it is inside every figure below. CPU = the same tasks' thread time, which ` +
      `other processes on the machine do not stretch. app = the page's own work in each frame it ` +
      `drew (derive + draw + panel, its "${FRAME_MEASURE}" measures), without the harness.`,
  );
  console.log(
    `\nDrag: main-thread time per frame; the ratio is to the reference page's p95, a canvas of the ` +
      `same size stroking one ${REFERENCE_SEGMENTS}-segment path per move, measured again ` +
      `(${report.checkFrames} frames) just before and just after each lesson's drags and pooled ` +
      `(${2 * report.checkFrames} frames), so that a machine slowing or speeding up through the run ` +
      `moves both figures of a ratio (${ms(reference)} ms in the check above)`,
  );
  printDrags(report.drags, reference);
  console.log('');
  printGallery(report.gallery, report.unfetched);
  console.log(
    `\nLessons: JS fetched on top of the gallery's, and load time = navigation → first drawn figure ` +
      `(fresh context each load)`,
  );
  printLoads(report.loads, report.loadRuns);
  console.log(
    report.markSeen
      ? `First drawn figure: the app's performance mark "${FIRST_DRAW_MARK}" (startTime); "watcher" ` +
          `rows fell back to ${FALLBACK_METHOD}.`
      : `First drawn figure: the app sets no "${FIRST_DRAW_MARK}" mark, so the watcher was used: ` +
          `${FALLBACK_METHOD}, then performance.now().`,
  );
}
