import type { Point } from '../../math';

/**
 * What is unusual about these villages, in words for the lecture: villages on
 * top of each other, all in one line, all in one place. Each method still
 * draws something; these sentences say why it looks as it does.
 */
export function villageNotes(v: readonly Point[]): string[] {
  const notes: string[] = [];
  let minX = Infinity;
  let maxX = -Infinity;
  let minY = Infinity;
  let maxY = -Infinity;
  for (const p of v) {
    minX = Math.min(minX, p[0]);
    maxX = Math.max(maxX, p[0]);
    minY = Math.min(minY, p[1]);
    maxY = Math.max(maxY, p[1]);
  }
  const extent = Math.hypot(maxX - minX, maxY - minY);
  if (extent === 0) {
    return [
      `All ${v.length} villages are in one place: every road has length zero, so there is nothing to draw but the village.`,
    ];
  }
  const repeats: string[] = [];
  for (let i = 0; i + 1 < v.length; i++) {
    if (v[i][0] === v[i + 1][0] && v[i][1] === v[i + 1][1]) repeats.push(`P${i} = P${i + 1}`);
  }
  if (repeats.length) {
    const shown = repeats.length > 4 ? `${repeats.slice(0, 4).join(', ')}, …` : repeats.join(', ');
    notes.push(
      `Villages on top of each other (${shown}): that segment has length zero but still one unit of p̄, so the road slows to a stop there or makes a small loop; the C² spline stays smooth in p̄ but the road may turn sharply.`,
    );
  }
  // All villages in a line: the furthest village from P0 fixes the line.
  let far = 0;
  for (let i = 1; i < v.length; i++) {
    if (dist(v[i], v[0]) > dist(v[far], v[0])) far = i;
  }
  const dx = v[far][0] - v[0][0];
  const dy = v[far][1] - v[0][1];
  const length = Math.hypot(dx, dy);
  // A loop, not Math.max(...v.map(…)): 500 villages on every drag frame.
  let offLine = 0;
  for (const p of v)
    offLine = Math.max(offLine, Math.abs((p[0] - v[0][0]) * dy - (p[1] - v[0][1]) * dx) / length);
  if (v.length > 2 && offLine <= 1e-9 * extent) {
    notes.push(
      'All villages lie on one line: every road through them runs along it, back and forth if need be, unless a chosen end gradient (or the quadratic’s first) points off it.',
    );
  }
  if (v.length === 2) {
    notes.push(
      'Two villages: one segment, a straight road for every method without a chosen gradient. The system has two rows, [2 1] and [1 2].',
    );
  }
  return notes;
}

const dist = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);
