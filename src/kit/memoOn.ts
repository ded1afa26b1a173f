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
  let last: { inputs: unknown[]; value: R } | null = null;
  return (state) => {
    const inputs = keys.map((key) => state[key]);
    if (last && inputs.every((value, i) => Object.is(value, last!.inputs[i]))) return last.value;
    const value = compute(state);
    last = { inputs, value };
    return value;
  };
}
