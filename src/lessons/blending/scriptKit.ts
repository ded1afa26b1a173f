import { SLOT } from '../../render/formula';
import type { FormulaParts } from '../../render/formulaParts';
import type { Painter } from '../../render/painter';

// Small helpers the stepped lessons (blending, lagrange, hermite, road) share.
// They belong in the shell (render/formulaParts.ts and render/painter.ts).

/** A live formula's TeX with its numbers filled in: for a step's formula in presenter view. */
export const filled = (parts: FormulaParts): string =>
  parts.shape.split(SLOT).reduce((tex, part, i) => tex + (parts.values[i - 1] ?? '') + part);

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

/** What is degenerate about a list of points: all on one spot, all on one line, neighbours on one spot. */
export interface Degenerate {
  allSame: boolean;
  /** Three or more points, all on one line (and not all on one spot). */
  collinear: boolean;
  /** Pairs of neighbours i, i + 1 on one spot. */
  repeats: number[];
}

export function degenerate(p: readonly (readonly number[])[]): Degenerate {
  let far = 0;
  const dist = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);
  for (let i = 1; i < p.length; i++) if (dist(p[i], p[0]) > dist(p[far], p[0])) far = i;
  const length = dist(p[far], p[0]);
  const allSame = length === 0;
  const [dx, dy] = [p[far][0] - p[0][0], p[far][1] - p[0][1]];
  const offLine = allSame
    ? 0
    : Math.max(...p.map((q) => Math.abs((q[0] - p[0][0]) * dy - (q[1] - p[0][1]) * dx) / length));
  const repeats: number[] = [];
  for (let i = 0; i + 1 < p.length; i++)
    if (p[i][0] === p[i + 1][0] && p[i][1] === p[i + 1][1]) repeats.push(i);
  return { allSame, collinear: !allSame && p.length > 2 && offLine <= 1e-9 * length, repeats };
}

/** "P1 = P2, P4 = P5": the repeated neighbours named (at most four). */
export function repeatsText(repeats: readonly number[], name = 'P'): string {
  const pairs = repeats.map((i) => `${name}${i} = ${name}${i + 1}`);
  return pairs.length > 4 ? `${pairs.slice(0, 4).join(', ')}, …` : pairs.join(', ');
}

/**
 * A plot's y-axis name, boxed just right of the axis at the top, so neither
 * the axis nor a curve runs through it. Returns the y (pixels) below it.
 */
export function plotYName(painter: Painter, minX: number, maxY: number, name: string): number {
  const small = painter.theme.sizes.small;
  const [x, y] = painter.view.toScreen([minX, maxY]);
  painter.screenLabel(name, x + small * 0.8, y + small * 0.9, {
    color: painter.theme.muted,
    size: small * 1.1,
    box: true,
  });
  return y + small * 2.2;
}

/**
 * The values at a plot's cursor, as a boxed column in the top corner away
 * from the cursor: never written over their own curves.
 */
export function valueColumn(
  painter: Painter,
  cursor: number,
  range: { minX: number; maxX: number },
  top: number,
  entries: readonly { text: string; color: string }[],
): void {
  const { view, theme } = painter;
  const size = theme.sizes.small;
  const [left] = view.toScreen([range.minX, 0]);
  const [far] = view.toScreen([range.maxX, 0]);
  const right = cursor < (range.minX + range.maxX) / 2;
  const edge = right ? Math.min(far, view.width) - size * 0.8 : Math.max(left, 0) + size * 0.8;
  // A plot too short for the column: the values go in a row along its top instead.
  if (top + entries.length * size * 1.75 > view.height * 0.8) {
    let x = Math.max(left, 0) + size * 0.8;
    for (const entry of entries) {
      const { width } = painter.screenLabel(entry.text, x, top + size * 0.6, {
        color: entry.color,
        size,
        bold: true,
        box: true,
      });
      x += width + size * 1.2;
    }
    return;
  }
  entries.forEach((entry, i) => {
    painter.screenLabel(entry.text, edge, top + size * 0.6 + i * size * 1.75, {
      color: entry.color,
      size,
      bold: true,
      box: true,
      align: right ? 'right' : 'left',
    });
  });
}

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
