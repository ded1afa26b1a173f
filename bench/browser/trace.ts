// Main-thread time per frame from a Chromium trace (the JSON that
// `browser.stopTracing()` returns, categories devtools.timeline and
// disabled-by-default-devtools.timeline).
//
// A frame is the time between two consecutive mouse moves: from the start of
// the top-level task that dispatches move i to the start of the one that
// dispatches move i + 1. Its main-thread time is the sum of the durations of
// the renderer main thread's top-level tasks that start in it (nested RunTasks
// are inside their parent's duration already).

interface TraceEvent {
  readonly name: string;
  readonly ph: string;
  readonly pid: number;
  readonly tid: number;
  readonly ts: number;
  readonly dur?: number;
  /** Thread (CPU) time, which a busy machine does not stretch. */
  readonly tdur?: number;
  readonly args?: {
    readonly name?: string;
    readonly data?: {
      readonly type?: string;
      readonly frames?: readonly { processId?: number; isOutermostMainFrame?: boolean }[];
    };
  };
}

interface Task {
  readonly start: number;
  readonly end: number;
  readonly cpu: number;
}

/** What one traced drag cost, frame by frame. */
export interface FrameTimes {
  /** Main-thread milliseconds of each frame (task durations), in order. */
  readonly perFrame: readonly number[];
  /** The same tasks' thread CPU milliseconds, frame by frame. */
  readonly cpuPerFrame: readonly number[];
  /** How many moves the page dispatched (one more than the frames, if none was merged). */
  readonly dispatchedMoves: number;
}

const TASK_NAMES = new Set(['RunTask', 'ThreadControllerImpl::RunTask']);

/** Splits a traced drag into frames at each dispatched move and sums each frame's tasks. */
export function mainThreadPerFrame(traceJson: string): FrameTimes {
  const parsed = JSON.parse(traceJson) as { traceEvents?: TraceEvent[] } | TraceEvent[];
  const events = Array.isArray(parsed) ? parsed : (parsed.traceEvents ?? []);
  const thread = rendererMainThread(events);
  if (!thread) return { perFrame: [], cpuPerFrame: [], dispatchedMoves: 0 };
  const onThread = events
    .filter((e) => e.pid === thread.pid && e.tid === thread.tid && e.ph === 'X')
    .sort((a, b) => a.ts - b.ts || (b.dur ?? 0) - (a.dur ?? 0));
  const tasks = topLevelTasks(onThread);
  const moves = dispatchedMoves(onThread);
  const boundaries = moves.map((move) => enclosingTask(tasks, move)?.start ?? move.ts);
  const perFrame: number[] = [];
  const cpuPerFrame: number[] = [];
  for (let i = 0; i + 1 < boundaries.length; i++) {
    let wall = 0;
    let cpu = 0;
    for (const task of tasks) {
      if (task.start < boundaries[i] || task.start >= boundaries[i + 1]) continue;
      wall += task.end - task.start;
      cpu += task.cpu;
    }
    perFrame.push(wall / 1000);
    cpuPerFrame.push(cpu / 1000);
  }
  return { perFrame, cpuPerFrame, dispatchedMoves: moves.length };
}

/** The page's renderer main thread: the process of the outermost main frame, else the busiest. */
function rendererMainThread(events: readonly TraceEvent[]): { pid: number; tid: number } | null {
  const mains = events.filter(
    (e) => e.ph === 'M' && e.name === 'thread_name' && e.args?.name === 'CrRendererMain',
  );
  const started = events.find((e) => e.name === 'TracingStartedInBrowser');
  const pagePid = started?.args?.data?.frames?.find((f) => f.isOutermostMainFrame)?.processId;
  const byPage = mains.find((m) => m.pid === pagePid);
  if (byPage) return { pid: byPage.pid, tid: byPage.tid };
  let best: { pid: number; tid: number } | null = null;
  let bestCount = 0;
  for (const m of mains) {
    const count = events.filter(
      (e) => e.pid === m.pid && e.tid === m.tid && e.name === 'EventDispatch',
    ).length;
    if (count > bestCount) [best, bestCount] = [{ pid: m.pid, tid: m.tid }, count];
  }
  return best;
}

/** Tasks not nested in an earlier one, from events sorted by start (longest first on ties). */
function topLevelTasks(sorted: readonly TraceEvent[]): Task[] {
  const tasks: Task[] = [];
  let end = -Infinity;
  for (const e of sorted) {
    if (!TASK_NAMES.has(e.name) || e.ts < end) continue;
    end = e.ts + (e.dur ?? 0);
    tasks.push({ start: e.ts, end, cpu: e.tdur ?? 0 });
  }
  return tasks;
}

/**
 * One dispatch per mouse move: pointermove where the page got pointer events,
 * else mousemove (a page that calls preventDefault on pointerdown gets no
 * mousemove; a range input gets both).
 */
function dispatchedMoves(sorted: readonly TraceEvent[]): TraceEvent[] {
  const of = (type: string) =>
    sorted.filter((e) => e.name === 'EventDispatch' && e.args?.data?.type === type);
  const pointer = of('pointermove');
  return pointer.length > 0 ? pointer : of('mousemove');
}

function enclosingTask(tasks: readonly Task[], e: TraceEvent): Task | undefined {
  return tasks.find((t) => t.start <= e.ts && t.end >= e.ts + (e.dur ?? 0));
}

/** The q-quantile (0..1) by linear interpolation between closest ranks. */
export function quantile(values: readonly number[], q: number): number {
  if (values.length === 0) return NaN;
  const sorted = values.slice().sort((a, b) => a - b);
  const at = q * (sorted.length - 1);
  const low = Math.floor(at);
  const high = Math.min(sorted.length - 1, low + 1);
  return sorted[low] + (sorted[high] - sorted[low]) * (at - low);
}
