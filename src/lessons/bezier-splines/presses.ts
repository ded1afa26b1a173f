// A run of repeated steps (one bᵢ, one joint) takes at most MOST_PRESSES
// presses: with many points each press shows several, so a scene stays within
// the clicker's 20 steps whatever the link holds.

export const MOST_PRESSES = 3;

/** How many presses `count` items take. */
export const presses = (count: number) => Math.min(Math.max(count, 0), MOST_PRESSES);

/** How many of `count` items presses 1 … k have shown. */
export const itemsShown = (count: number, k: number) =>
  k <= 0 ? 0 : Math.floor((Math.min(k, presses(count)) * count) / presses(count));

/** The items (1-based) press k of `count` shows. */
export function pressItems(count: number, k: number): number[] {
  const from = itemsShown(count, k - 1) + 1;
  const to = itemsShown(count, k);
  return Array.from({ length: Math.max(0, to - from + 1) }, (_, i) => from + i);
}
