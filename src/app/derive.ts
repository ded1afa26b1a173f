/**
 * A lesson's model is derived once per state. States are immutable objects,
 * so the state object itself is the key: a new state is a new object, and an
 * unchanged one finds its model again (Excalidraw caches each shape's
 * geometry the same way).
 */
export function memoize<S, M>(derive: (state: S) => M): (state: S) => M {
  const cache = new WeakMap<object, M>();
  let lastKey: unknown = undefined;
  let lastModel: M | undefined;
  return (state: S) => {
    if (state === lastKey) return lastModel as M;
    let model: M;
    if (typeof state === 'object' && state !== null) {
      const hit = cache.get(state);
      if (hit !== undefined) model = hit;
      else {
        model = derive(state);
        cache.set(state, model);
      }
    } else model = derive(state);
    lastKey = state;
    lastModel = model;
    return model;
  };
}
