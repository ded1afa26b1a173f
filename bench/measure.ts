// Timing helper for the benchmarks: warm up (so V8 has optimised both sides),
// then the median of several runs, each after a forced GC when node runs with
// --expose-gc, so one side does not pay for the other's garbage.
//
// BENCH_CLOCK=cpu times the process's CPU time (user + system, all its
// threads, so GC helpers count) instead of wall time: on a machine shared with
// other work, time spent waiting for a core then does not count.

export interface Timing {
  /** Median time of one run (wall, or CPU with BENCH_CLOCK=cpu), in milliseconds. */
  readonly median: number;
  /** Every measured run, in milliseconds. */
  readonly runs: readonly number[];
}

const collectGarbage = (globalThis as { gc?: () => void }).gc;

/** Which clock measure() reads, for the benchmark's heading. */
export const clock = process.env.BENCH_CLOCK === 'cpu' ? 'CPU time' : 'wall time';

function now(): number {
  if (clock === 'wall time') return performance.now();
  const { user, system } = process.cpuUsage();
  return (user + system) / 1000;
}

/**
 * Times `run` (which may use `setup`'s fresh state each time, untimed).
 * Returns the median of `runs` measurements after `warmups` untimed calls.
 */
export function measure<State>(
  setup: () => State,
  run: (state: State) => unknown,
  { warmups = 3, runs = 9 }: { warmups?: number; runs?: number } = {},
): Timing {
  let sink = 0;
  const keep = (value: unknown) => {
    // Touch the result so the optimiser cannot drop the work.
    if (value !== undefined && value !== null) sink++;
  };
  for (let i = 0; i < warmups; i++) keep(run(setup()));
  const times: number[] = [];
  for (let i = 0; i < runs; i++) {
    const state = setup();
    collectGarbage?.();
    const start = now();
    keep(run(state));
    times.push(now() - start);
  }
  if (sink < 0) console.log(sink);
  const sorted = times.slice().sort((a, b) => a - b);
  return { median: sorted[Math.floor(sorted.length / 2)], runs: times };
}
