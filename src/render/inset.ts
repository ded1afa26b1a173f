/**
 * A magnified inset: a small region of a figure drawn again, larger, in a
 * framed box in the corner where it hides least (no corner over a handle or
 * the region itself). For a detail the figure's
 * scale makes too small to see: a loop 50 px wide on the projector, under two
 * handles. The figure keeps its view (and its size through the steps); the
 * region is marked on it with a square in the inset's colour.
 */
import { type Box, boxesMeet } from './ink';
import { Painter } from './painter';
import { type Bounds, Viewport } from './viewport';

export interface InsetSpec {
  /** The world region to magnify: it fills most of the box. */
  region: Bounds;
  /** At most this many times larger than the figure (12 unless said); at least twice. */
  maxZoom?: number;
  /** World points the box must leave uncovered: the figure's handles. */
  avoid?: readonly (readonly number[])[];
  /** The frame's and the region square's colour. */
  color?: string;
}

/** The inset's side, as a share of the figure's shorter side. */
const SIDE = 0.36;

/**
 * Draws `spec.region` magnified in a corner box, `draw` painting it with a
 * painter of its own (its view magnified, its drawing clipped to the box).
 * Returns the box, or null where no corner leaves the region and the handles
 * uncovered, or the figure is too small (then nothing is drawn). The box is
 * ink on the figure's painter: no label is placed on it.
 */
export function drawInset(
  painter: Painter,
  spec: InsetSpec,
  draw: (inset: Painter) => void,
): Box | null {
  const { view, theme, ctx } = painter;
  if (!(view instanceof Viewport)) return null;
  const side = Math.round(Math.min(view.width, view.height) * SIDE);
  const { minX, minY, maxX, maxY } = spec.region;
  const around = [(minX + maxX) / 2, (minY + maxY) / 2];
  // The region fills 80% of the box, magnified at least twice.
  const span = Math.max((maxX - minX) * view.scaleX, (maxY - minY) * view.scaleY, 1e-9);
  const zoom = Math.max(2, Math.min(spec.maxZoom ?? 12, (0.8 * side) / span));
  const gap = theme.sizes.handle;
  const [cx, cy] = view.toScreen(around);
  if (!Number.isFinite(cx) || !Number.isFinite(cy) || side < 80) return null;
  const seen = side / zoom;
  const region: Box = { x: cx - seen / 2, y: cy - seen / 2, width: seen, height: seen };
  const reach = theme.sizes.handle * 2;
  const handles = (spec.avoid ?? []).map((p) => view.toScreen(p));
  const right = view.width - side - gap;
  const bottom = view.height - side - gap;
  const free = [
    { x: right, y: bottom },
    { x: right, y: gap },
    { x: gap, y: bottom },
    { x: gap, y: gap },
  ]
    .map(({ x, y }) => ({ x, y, width: side, height: side }))
    .filter(
      (box) =>
        !boxesMeet(box, region) &&
        handles.every(([hx, hy]) => !boxesMeet(box, square(hx, hy, reach))),
    );
  if (!free.length) return null;
  const cost = (box: Box) => {
    const { discs, strokes } = painter.ink.hits(box);
    return discs * 1000 + strokes;
  };
  const box = free.reduce((best, next) => (cost(next) < cost(best) ? next : best));

  const magnified = new Viewport(view.width, view.height);
  magnified.scaleX = view.scaleX * zoom;
  magnified.scaleY = view.scaleY * zoom;
  magnified.centerX = around[0] - (box.x + side / 2 - view.width / 2) / magnified.scaleX;
  magnified.centerY = around[1] + (box.y + side / 2 - view.height / 2) / magnified.scaleY;
  ctx.save();
  ctx.globalAlpha = 1;
  ctx.fillStyle = theme.background;
  ctx.fillRect(box.x, box.y, side, side);
  ctx.beginPath();
  ctx.rect(box.x, box.y, side, side);
  ctx.clip();
  const clip = { minX: box.x, minY: box.y, maxX: box.x + side, maxY: box.y + side };
  const inset = new Painter(ctx, magnified, theme, painter.show, clip);
  draw(inset);
  // How much larger, in its top left corner (over what it shows: its own box, no other label's).
  const size = theme.sizes.small;
  inset.screenLabel(`×${Math.round(zoom)}`, box.x + size * 0.4, box.y + size * 0.8, {
    size,
    color: spec.color ?? theme.accent,
    halo: true,
    bold: true,
    inBox: true,
  });
  ctx.restore();

  const color = spec.color ?? theme.accent;
  const outline = (b: Box, width: number) =>
    painter.polyline(
      [
        view.toWorld([b.x, b.y]),
        view.toWorld([b.x + b.width, b.y]),
        view.toWorld([b.x + b.width, b.y + b.height]),
        view.toWorld([b.x, b.y + b.height]),
      ],
      { color, width },
      true,
    );
  outline(region, theme.sizes.thin);
  outline(box, theme.sizes.line);
  painter.ink.area(box);
  return box;
}

const square = (x: number, y: number, r: number): Box => ({
  x: x - r,
  y: y - r,
  width: 2 * r,
  height: 2 * r,
});
