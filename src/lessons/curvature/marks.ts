import type { Point } from '../../math';
import type { Painter } from '../../render/painter';

/** Frame vectors are drawn this long: a round length near a quarter of the curve's size. */
export function arrowUnit(size: number): number {
  return 10 ** Math.round(Math.log10(size / 4));
}

/** The colours of T, N, B, κ throughout the lesson (figures, plot and panel). */
export const COLOURS = { tangent: 0, normal: 1, binormal: 2, curvature: 3, torsion: 2 } as const;

/** An arrow from p along v (scaled by `length`), labelled at its tip. */
export function vectorArrow(
  painter: Painter,
  p: Point,
  v: Point,
  length: number,
  label: string,
  colour: string,
  labels: boolean,
): void {
  const tip = p.map((x, d) => x + length * v[d]);
  painter.arrow(p, tip, { color: colour, width: painter.theme.sizes.line * 1.4 });
  if (labels)
    painter.label(label, tip, {
      color: colour,
      halo: true,
      bold: true,
      dx: 6,
      dy: -6,
      size: painter.theme.sizes.label,
    });
}
