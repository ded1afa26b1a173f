/**
 * The colours a painter picks from its theme: a series' colour by its
 * index, and the tint a filled region is drawn in.
 */
import type { Theme } from './theme';

/** The least opacity of a filled region's tint on the projector. */
const PROJECTOR_TINT = 0.25;

/** The palette's colour for series `i`: any integer, negative too, as the palette repeats. */
export function paletteColor(theme: Theme, i: number): string {
  const p = theme.palette;
  return p[((i % p.length) + p.length) % p.length];
}

/**
 * A filled region's opacity: on the projector a tint is at least a quarter
 * opaque: paler, a weak projector washes it out to the background (#19).
 */
export function regionTint(theme: Theme, alpha: number): number {
  return theme.projector ? Math.max(alpha, PROJECTOR_TINT) : alpha;
}
