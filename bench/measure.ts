// Timing helper for the benchmarks: warm up (so V8 has optimised both sides),
// then the median of several runs, each after a forced GC when node runs with
// --expose-gc, so one side does not pay for the other's garbage.

export interface Timing {
  /** Median wall time of one run, in milliseconds. */
  readonly median: number;
  /** Every measured run, in milliseconds. */
  readonly runs: readonly number[];
}

const collectGarbage = (globalThis as { gc?: () => void }).gc;

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
    const start = performance.now();
    keep(run(state));
    times.push(performance.now() - start);
  }
  if (sink < 0) console.log(sink);
  const sorted = times.slice().sort((a, b) => a - b);
  return { median: sorted[Math.floor(sorted.length / 2)], runs: times };
}
