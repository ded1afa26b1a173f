import type { Painter } from '../render/painter';
import type { Theme } from '../render/theme';

// Colours and dashes for series of curves, so a family of curves (the
// levels of a construction, the functions of a basis) stays told apart in
// every theme, for colour-blind viewers and in print.

/**
 * Palette slots for series drawn beside the accent: every theme's accent
 * (the colour of P(t) and of the parameter's marks) is slot 1 or 4, so a
 * series skips both and never wears the accent's colour. The first four
 * (a construction's levels, a family of curves) are blue, green, magenta and
 * brown: the light blue (slot 5) beside the dark one read as one colour on a
 * washed-out projector (#19), so it comes later (seriesColours.test.ts).
 */
const SERIES_SLOTS = [0, 2, 3, 7, 5, 6];

/** The k-th colour of a series that never takes the accent's colour. */
export const seriesColour = (palette: Theme['palette'], k: number) =>
  palette[SERIES_SLOTS[k % SERIES_SLOTS.length] % palette.length];

/** Levels take the first four series colours; the last two are kept for the halves. */
const LEVEL_COLOURS = 4;

/** The colour of level r (r ≥ 1); it repeats after four levels, with a dash to tell them apart. */
export const levelColour = (palette: Theme['palette'], r: number) =>
  seriesColour(palette, (r - 1) % LEVEL_COLOURS);

/** Solid for levels 1–4, long dashes for 5–8, dots beyond. */
export const levelDash = (r: number): number[] | undefined =>
  r <= LEVEL_COLOURS ? undefined : r <= 2 * LEVEL_COLOURS ? [14, 5] : [3, 5];

/** The left (0) and right (1) half of the subdivision: a colour of its own and a dash of its own. */
export const halfColour = (palette: Theme['palette'], k: 0 | 1) =>
  seriesColour(palette, LEVEL_COLOURS + k);
/** The dash of the left (0) and right (1) half, with `halfColour`. */
export const HALF_DASH: [number[], number[]] = [
  [16, 6],
  [4, 6],
];

/**
 * Series i beyond the palette repeats a colour: it is told apart by a dash
 * (one pattern per round of the palette), so N = 10 or 11 curves stay distinct
 * for colour-blind viewers and in print. Undefined within the palette.
 */
export function seriesDash(painter: Painter, i: number): number[] | undefined {
  const round = Math.floor(i / painter.theme.palette.length);
  if (round === 0) return undefined;
  const unit = painter.theme.sizes.line * 1.6;
  return round === 1 ? [unit * 3, unit * 1.6] : [unit, unit * 1.4];
}
