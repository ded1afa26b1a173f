/**
 * Typesetting within a frame's budget. A new scene can bring a page of new
 * formulas (an 11 × 11 matrix takes 35 ms): typeset in one frame they would
 * hold the pointer and the keys up for that long. While a budget is open
 * (the lesson page opens one per frame), a typeset that would start after it
 * is spent waits, newest text kept, for the next frame's budget; at least
 * one typeset is done per frame, so the queue always drains. Outside a
 * frame's budget (building a panel, the gallery) typesetting is immediate.
 */
const waiting = new Map<object, () => void>();
let budgetEnd = Number.POSITIVE_INFINITY;
let typesetThisFrame = 0;
/**
 * How long the last typeset took: the next one starts within a frame's budget
 * only if one as long would still end inside it (a check of the clock alone
 * let a 19 ms formula and a 33 ms one share a 20 ms budget: a 53 ms frame).
 */
let lastJob = 0;

/** Would one more typeset, as long as the last, end past the frame's budget? */
const overBudget = () => typesetThisFrame > 0 && performance.now() + lastJob > budgetEnd;

function run(job: () => void): void {
  typesetThisFrame++;
  const start = performance.now();
  job();
  lastJob = performance.now() - start;
}

/**
 * Runs `job` (a typeset, a measurement of one) now or, past this frame's
 * budget, in a later frame's: the last job given for an owner wins.
 */
export function typesetSoon(owner: object, job: () => void): void {
  waiting.delete(owner);
  if (overBudget()) {
    waiting.set(owner, job);
    return;
  }
  run(job);
}

/**
 * Opens a frame's typesetting budget and does what waited from the last
 * frames within it; says how many waiting formulas it typeset.
 */
export function openTypesetBudget(milliseconds: number): number {
  budgetEnd = performance.now() + milliseconds;
  typesetThisFrame = 0;
  for (const [owner, job] of [...waiting]) {
    if (overBudget()) break;
    waiting.delete(owner);
    run(job);
  }
  return typesetThisFrame;
}

/** Closes the frame's budget: typesetting is immediate again until the next frame. */
export function closeTypesetBudget(): void {
  budgetEnd = Number.POSITIVE_INFINITY;
  typesetThisFrame = 0;
}

/** Formulas still waiting for a frame to be typeset in. */
export function typesetWaiting(): boolean {
  return waiting.size > 0;
}
