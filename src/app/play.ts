/**
 * The value Play moves to next: `amount` further on, wrapping to the start
 * past the end, and always inside [min, max]. The first animation frame's
 * timestamp can be earlier than the press that started Play, so `amount` can
 * be negative; a played value must never leave its range (a basis evaluated
 * at t = −0.0002 throws).
 */
export function nextPlayedValue(value: number, amount: number, min: number, max: number): number {
  let v = value + Math.max(0, amount);
  if (v > max + 1e-12) v = min;
  return Math.min(max, Math.max(min, Number(v.toPrecision(12))));
}
