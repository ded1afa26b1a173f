/** Whether two lists hold the same values, each compared by identity (`Object.is`). */
export function sameValues(a: readonly unknown[], b: readonly unknown[]): boolean {
  return a.length === b.length && a.every((value, i) => Object.is(value, b[i]));
}

/**
 * A value computed from some fields of a state, kept while those fields are
 * the same (by identity: states are never mutated, so an unchanged field is
 * the same object). A step or a view change then costs nothing: the spline
 * is solved again only when its points or its parameter change. (As
 * Excalidraw caches each shape's geometry, keyed by the element.)
 */
export function memoOn<S, K extends keyof S, R>(
  keys: readonly K[],
  compute: (fields: Pick<S, K>) => R,
): (state: S) => R {
  const last = memoLast((state: S) => compute(state));
  return (state) =>
    last.keyed(
      keys.map((key) => state[key]),
      state,
    );
}

/** A function that remembers its last answer, and the values it was computed from. */
export interface MemoLast<A extends readonly unknown[], R> {
  (...args: A): R;
  /** The answer for `args`, computed again only if `key` differs from the last call's key. */
  keyed(key: readonly unknown[], ...args: A): R;
}

/**
 * `compute`, remembered for its last arguments (each compared by identity, so
 * numbers by value): called again with the same ones, it costs nothing. For
 * work on a drag's hot path that depends on less than what moves, such as
 * where a surface's point names may go, which depends on the net and the
 * view, not on the point (u, v) dragged across it.
 */
export function memoLast<A extends readonly unknown[], R>(
  compute: (...args: A) => R,
): MemoLast<A, R> {
  let last: { key: readonly unknown[]; value: R } | null = null;
  const keyed = (key: readonly unknown[], ...args: A): R => {
    if (last && sameValues(key, last.key)) return last.value;
    const value = compute(...args);
    last = { key, value };
    return value;
  };
  return Object.assign((...args: A) => keyed(args, ...args), { keyed });
}
