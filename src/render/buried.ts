/**
 * How much of a figure's subject (its strokes of role 'curve': the road, the
 * Bézier curve, the spline) lies under handles, as drawn. A curve threaded
 * through hundreds of points can vanish under their handles: what the tests
 * look for on every step.
 */
import type { Ink } from './ink';

/**
 * The share (0 to 1) of the subject's ink that handles hide: a stretch of a
 * stroke counts as hidden where a handle, as drawn, covers its whole width (a
 * dot narrower than the road leaves the road seen on either side of it), and
 * each stroke counts by its width. 0 when there is no subject.
 */
export function subjectUnderHandles(ink: Ink): number {
  const discs = ink.handles;
  const runs = ink.subjectRuns;
  if (!runs.length) return 0;
  // The handles by grid cell, a cell as wide as the largest handle: a point's
  // handles are in its own cell and the eight around it.
  let cell = 1;
  for (let i = 3; i < discs.length; i += 4) cell = Math.max(cell, discs[i]);
  const cells = new Map<string, number[]>();
  for (let i = 0; i < discs.length; i += 4) {
    const key = `${Math.floor(discs[i] / cell)},${Math.floor(discs[i + 1] / cell)}`;
    const list = cells.get(key) ?? [];
    list.push(i);
    cells.set(key, list);
  }
  const covered = (x: number, y: number, half: number) => {
    const [cx, cy] = [Math.floor(x / cell), Math.floor(y / cell)];
    for (let dx = -1; dx <= 1; dx++)
      for (let dy = -1; dy <= 1; dy++)
        for (const i of cells.get(`${cx + dx},${cy + dy}`) ?? [])
          if ((discs[i] - x) ** 2 + (discs[i + 1] - y) ** 2 + half * half < discs[i + 3] ** 2)
            return true;
    return false;
  };
  let total = 0;
  let under = 0;
  for (let r = 0; r < runs.length; r += 2)
    for (let i = runs[r]; i < runs[r + 1]; i++) {
      const [x1, y1, x2, y2, half] = ink.segmentAt(i);
      const length = Math.hypot(x2 - x1, y2 - y1);
      if (!Number.isFinite(length)) continue;
      // Sampled about every pixel along the segment, each sample weighed by the stroke's width.
      const n = Math.max(1, Math.ceil(length));
      const area = (length / n) * half;
      for (let k = 0; k < n; k++) {
        const t = (k + 0.5) / n;
        total += area;
        if (covered(x1 + (x2 - x1) * t, y1 + (y2 - y1) * t, half)) under += area;
      }
    }
  return total > 0 ? under / total : 0;
}
