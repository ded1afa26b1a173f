/**
 * An edit that changes the number of steps (a point added, a comparison
 * switched on) keeps "everything shown" when everything was shown: the new
 * last step, not the old one.
 */
export function keepLastStep<S extends { step: number }>(
  before: S,
  after: S,
  count: (state: S) => number,
): S {
  return before.step >= count(before) ? { ...after, step: count(after) } : after;
}
