import type { Point } from '../../math';
import { edgePlaces, firstClear } from '../../render/boxPlaces';
import { labelWidth } from '../../render/labelWidth';
import type { Painter } from '../../render/painter';
import type { Polyline } from './model';
import type { Pixel, RasterSize } from './raster';

// Drawing pieces both figures use: pixels, a polyline with its computed
// points, the largest gap. Pixels are drawn in world units: pixel (i, j) of a
// raster with `zoom` pixels per unit is the square [i, i + 1] × [j, j + 1] / zoom.

/** The pixel square of (i, j), in world units. */
export const pixelSquare = (i: number, j: number, zoom: number): Point[] => [
  [i / zoom, j / zoom],
  [(i + 1) / zoom, j / zoom],
  [(i + 1) / zoom, (j + 1) / zoom],
  [i / zoom, (j + 1) / zoom],
];

/** Fills pixels, each with alpha `value · alpha` (coverage shades, or 1 for lit). */
export function fillPixels(
  painter: Painter,
  pixels: Iterable<Pixel>,
  zoom: number,
  color: string,
  alpha = 1,
): void {
  for (const { i, j, value } of pixels)
    painter.polygon(pixelSquare(i, j, zoom), color, value * alpha);
}

/** The pixel grid of a raster (lines only where they are far enough apart to read), and its frame. */
export function pixelGrid(painter: Painter, size: RasterSize): void {
  const theme = painter.theme;
  const { zoom, left, bottom, width, height } = size;
  const spacing = 1 / zoom / painter.view.worldLength(1);
  const style = { color: theme.axis, width: 1, alpha: 0.55, role: 'grid' as const };
  const [x0, y0, x1, y1] = [
    left / zoom,
    bottom / zoom,
    (left + width) / zoom,
    (bottom + height) / zoom,
  ];
  if (spacing >= 5) {
    for (let i = left; i <= left + width; i++)
      painter.segment([i / zoom, y0], [i / zoom, y1], style);
    for (let j = bottom; j <= bottom + height; j++)
      painter.segment([x0, j / zoom], [x1, j / zoom], style);
  }
  painter.polyline(
    [
      [x0, y0],
      [x1, y0],
      [x1, y1],
      [x0, y1],
    ],
    { color: theme.axis, width: theme.sizes.thin * 1.5 },
    true,
  );
}

/** A polyline with its vertices (the computed points on the curve). */
export function drawPolyline(painter: Painter, points: readonly Point[], color: string): void {
  painter.polyline(points, { color, width: painter.theme.sizes.line * 1.3 });
  for (const p of points) painter.dot(p, color, painter.theme.sizes.point * 0.8);
}

/** The largest gap between the curve and the polyline: a ring on the curve, a line to the chord, its size. */
export function drawGap(
  painter: Painter,
  polyline: Polyline,
  zoom: number,
  labels: boolean,
  color = painter.theme.accent,
): void {
  const { point, foot, distance } = polyline.deviation;
  const theme = painter.theme;
  painter.segment(point, foot, { color, width: theme.sizes.line * 1.4 });
  painter.ring(point, theme.sizes.point * 2, { color, width: theme.sizes.line });
  if (labels) {
    painter.label(`${(distance * zoom).toFixed(2)} px`, point, {
      dx: theme.sizes.point * 2.5,
      dy: -theme.sizes.point * 2.5,
      color,
      halo: true,
      bold: true,
    });
  }
}

/** The curve: the lesson's result, which the presenter can hide. */
export function drawCurve(painter: Painter, curve: Float64Array, faint = false): void {
  const theme = painter.theme;
  painter.polylineFlat(curve, {
    color: faint ? theme.curveFaint : theme.curve,
    width: faint ? theme.sizes.curve * 0.8 : theme.sizes.curve,
    role: 'curve',
  });
}

/**
 * A heading in the first corner of the figure (top left, top right, bottom
 * left, …) where no stroke, point or axis runs under it, once the figure's
 * ink is down; where none is clear, at the top left, moved or boxed by the
 * placer like any label.
 */
export function heading(painter: Painter, text: string): void {
  const { sizes } = painter.theme;
  const { width: across } = painter.view;
  const width = (line: string, size: number) => labelWidth(painter, line, { bold: true, size });
  // As large as fits the figure's width, down to the least size; then on two lines.
  const least = sizes.minText ?? sizes.small;
  const fitIn = (room: number) => (line: string) =>
    Math.max(least, Math.min(sizes.label, (sizes.label * room) / width(line, sizes.label)));
  // Or, if it costs at most a fifth of its size, as large as fits beside the
  // grid's y-axis: on a phone the axis ran through it, and it was boxed.
  const cuts = painter.ink.uprightRules().filter((x) => x > 0 && x < across);
  const stops = [0, ...cuts.sort((a, b) => a - b), across];
  const open = Math.max(...stops.slice(1).map((x, i) => x - stops[i]));
  const whole = across - sizes.label * 1.2;
  const beside = open - sizes.label * 1.2;
  const room = fitIn(beside)(text) >= 0.8 * fitIn(whole)(text) ? beside : whole;
  const fit = fitIn(room);
  const split = text.indexOf(': ');
  const lines =
    width(text, fit(text)) <= room || split < 0
      ? [text]
      : [text.slice(0, split + 1), text.slice(split + 2)];
  const size = Math.min(...lines.map(fit));
  const style = { bold: true, halo: true, size };
  const margin = sizes.label * 0.6;
  // Each line's box is 1.3 of its size tall, its middle 0.65 below its top.
  const block = {
    width: Math.max(...lines.map((line) => width(line, size))),
    height: lines.length * size * 1.3,
  };
  painter.placing(() => {
    const corners = edgePlaces(painter.view, block.width, block.height, margin, size * 0.45);
    const clear = firstClear(painter, corners, false);
    const { x, y } = clear >= 0 ? corners[clear] : corners[0];
    lines.forEach((line, i) =>
      painter.screenLabel(line, x, y + size * (0.65 + 1.3 * i), {
        ...style,
        fixed: clear >= 0,
      }),
    );
  });
}
