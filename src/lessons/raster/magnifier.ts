import { labelFrame, type LabelStyle } from '../../render/labels';
import { labelWidth } from '../../render/labelWidth';
import type { Painter } from '../../render/painter';
import type { Bounds } from '../../render/projection';
import type { RasterModel } from './model';

// One segment magnified, in pixel coordinates: pixel (i, j) is the square
// [i − ½, i + ½] × [j − ½, j + ½], so pixel centres are whole numbers.

function region(m: RasterModel) {
  const { pixels } = m.line;
  const is = pixels.map((p) => p[0]);
  const js = pixels.map((p) => p[1]);
  return {
    minI: Math.min(...is) - 1,
    maxI: Math.max(...is) + 1,
    minJ: Math.min(...js) - 1,
    maxJ: Math.max(...js) + 1,
  };
}

export function magnifierBounds(m: RasterModel): Bounds {
  const r = region(m);
  return { minX: r.minI - 0.5, maxX: r.maxI + 0.5, minY: r.minJ - 0.5, maxY: r.maxJ + 0.5 };
}

const square = (i: number, j: number) => [
  [i - 0.5, j - 0.5],
  [i + 0.5, j - 0.5],
  [i + 0.5, j + 0.5],
  [i - 0.5, j + 0.5],
];

function grid(painter: Painter, m: RasterModel, labels: boolean): void {
  const r = region(m);
  const theme = painter.theme;
  const style = { color: theme.axis, width: 1, alpha: 0.7 };
  for (let i = r.minI; i <= r.maxI + 1; i++)
    painter.segment([i - 0.5, r.minJ - 0.5], [i - 0.5, r.maxJ + 0.5], style);
  for (let j = r.minJ; j <= r.maxJ + 1; j++)
    painter.segment([r.minI - 0.5, j - 0.5], [r.maxI + 0.5, j - 0.5], style);
  if (!labels) return;
  // Column and row numbers where there is room for them.
  const room = 1 / painter.view.worldLength(1);
  const every = Math.max(1, Math.ceil((theme.sizes.small * 2.2) / room));
  const small = {
    size: theme.sizes.small,
    color: theme.muted,
    align: 'center' as const,
    halo: true,
  };
  for (let i = r.minI; i <= r.maxI; i += every)
    painter.label(String(i), [i, r.minJ - 0.5], { ...small, dy: theme.sizes.small });
  for (let j = r.minJ; j <= r.maxJ; j += every)
    painter.label(String(j), [r.minI - 0.5, j], { ...small, dx: -theme.sizes.small });
}

export function drawMagnifier(painter: Painter, m: RasterModel, labels: boolean): void {
  const theme = painter.theme;
  const { line, shown } = m;
  const pixels = m.segmentCoverage;
  if (pixels) {
    const shares = shown.has('shares');
    if (shares)
      for (const { i, j, value } of pixels) painter.polygon(square(i, j), theme.ink, value * 0.85);
    grid(painter, m, labels);
    // The strip one pixel wide around the segment.
    const [u0, v0] = line.from;
    const [u1, v1] = line.to;
    const length = Math.hypot(u1 - u0, v1 - v0) || 1;
    const [nx, ny] = [(-(v1 - v0) / length) * 0.5, ((u1 - u0) / length) * 0.5];
    painter.polygon(
      [
        [u0 + nx, v0 + ny],
        [u1 + nx, v1 + ny],
        [u1 - nx, v1 - ny],
        [u0 - nx, v0 - ny],
      ],
      painter.color(0),
      shares ? 0.12 : 0.3,
      { color: painter.color(0), width: theme.sizes.line },
    );
    const look = shares && labels ? shareLook(painter) : null;
    // Each share in its own pixel, over the strip's edge where that crosses
    // it: moved clear of the edge, a share was read as its neighbour's (0.70
    // on a white pixel above the dark one it belongs to).
    if (look)
      for (const { i, j, value } of pixels.filter((pixel) => pixel.value >= 0.005))
        painter.label(value.toFixed(2), [i, j], look);
    return;
  }
  const all = shown.has('everySegment');
  const lit = m.pixelsShown;
  for (const [i, j] of line.pixels.slice(0, lit)) painter.polygon(square(i, j), theme.accent, 0.75);
  grid(painter, m, labels);
  const [u0, v0] = line.from;
  const [u1, v1] = line.to;
  painter.segment([u0, v0], [u1, v1], { color: painter.color(0), width: theme.sizes.line * 1.3 });
  if (!shown.has('ends')) return;
  const { first, last } = line;
  painter.segment(first, last, { color: theme.ink, width: theme.sizes.thin, dash: [6, 5] });
  for (const [i, j] of [first, last])
    painter.polyline(square(i, j), { color: theme.accent, width: theme.sizes.line * 1.2 }, true);
  const cross = (index: number) =>
    line.major === 'x'
      ? [line.pixels[index][0], line.ideal[index]]
      : [line.ideal[index], line.pixels[index][1]];
  for (let index = 0; index < lit; index++) {
    painter.dot(line.pixels[index], theme.ink, theme.sizes.point * 0.5);
    painter.dot(cross(index), painter.color(0), theme.sizes.point * 0.6);
  }
  if (!all && lit > 0 && labels) {
    const index = lit - 1;
    const value = line.ideal[index].toFixed(2);
    const [i, j] = line.pixels[index];
    const text = line.major === 'x' ? `y = ${value} → ${j}` : `x = ${value} → ${i}`;
    painter.label(text, [i, j], {
      dx: theme.sizes.label,
      dy: -theme.sizes.label * 1.2,
      bold: true,
      box: true,
    });
  }
}

/**
 * How a pixel's share is written: boxed where the box fits in the pixel, on a
 * halo where only the digits do, else not at all. A fixed ratio of pixel to
 * type said it fitted at a 1366 × 768 projector (57 px pixels), and each box,
 * 64 px wide, hid the last digit of the one before ("0.0", "0.3").
 */
function shareLook(painter: Painter): LabelStyle | null {
  const theme = painter.theme;
  const size = theme.sizes.small * 0.8;
  const cell = 1 / painter.view.worldLength(1);
  const style: LabelStyle = {
    size,
    align: 'center',
    baseline: 'middle',
    color: theme.ink,
    stays: true,
  };
  // Every share has the same digits' width: "0.00".
  const digits = labelWidth(painter, '0.00', style);
  const gap = size * 0.2;
  const frame = labelFrame(0, 0, digits, size);
  if (frame.width + gap <= cell && frame.height + gap <= cell) return { ...style, box: true };
  if (digits + 2 * gap <= cell) return { ...style, halo: true };
  return null;
}
