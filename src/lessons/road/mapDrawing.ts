import {
  type Point,
  bezierFrenetFrame,
  bezierPoint,
  bezierTangent,
  elevateDegree,
} from '../../math';
import type { Painter } from '../../render/painter';
import { CURVES, type Road } from './roads';

/** A piece of degree 1 or 2 as the cubic it equals, so all roads draw as exact cubics. */
export function asCubic(piece: readonly Point[]): Point[] {
  let cubic: Point[] = piece.slice();
  while (cubic.length < 4) cubic = elevateDegree(cubic);
  return cubic;
}

/** A road drawn as a road: dark casing, coloured surface, dashed centre line. */
export function drawRoadway(painter: Painter, pieces: readonly Point[][], color: string): void {
  const { theme } = painter;
  const cubics = pieces.map(asCubic);
  const w = theme.sizes.curve;
  painter.cubicSegments(cubics, { color: theme.ink, width: w * 3.4 });
  painter.cubicSegments(cubics, { color, width: w * 2.4 });
  painter.cubicSegments(cubics, {
    color: theme.background,
    width: Math.max(1, theme.sizes.thin),
    dash: [w * 2.5, w * 2.5],
  });
}

/** One curve of the overlay: a coloured line, dashed so curves differ in print too. */
export function drawOverlayCurve(painter: Painter, road: Road, index: number): void {
  const style = {
    color: painter.color(index),
    width: painter.theme.sizes.curve * 0.9,
    dash: CURVES[index].dash.map((d) => d * painter.theme.sizes.line * 0.6),
  };
  if (road.kind === 'pieces') painter.cubicSegments(road.pieces.map(asCubic), style);
  else if (road.kind === 'polyline') painter.polylineFlat(road.coords, style);
}

/** The legend of the overlay, top left: a line sample and the name of each curve. */
export function drawLegend(
  painter: Painter,
  entries: readonly { index: number; missing: string | null }[],
): number {
  const { theme, view } = painter;
  const size = theme.sizes.small * 1.05;
  const lineHeight = size * 1.45;
  const left = size * 0.8;
  const sample = size * 2.6;
  let y = size * 1.2;
  const width = Math.max(
    ...entries.map((e) =>
      measure(painter, CURVES[e.index].name + (e.missing ? ' (not drawn)' : ''), size),
    ),
  );
  painter.ctx.save();
  painter.ctx.globalAlpha = 0.9;
  painter.ctx.fillStyle = theme.labelHalo;
  painter.ctx.fillRect(
    left - size * 0.4,
    y - lineHeight * 0.6,
    sample + width + size * 1.6,
    lineHeight * entries.length + size * 0.2,
  );
  painter.ctx.restore();
  for (const entry of entries) {
    const curve = CURVES[entry.index];
    const a = view.toWorld([left, y]);
    const b = view.toWorld([left + sample, y]);
    painter.polyline([a, b], {
      color: painter.color(entry.index),
      width: theme.sizes.curve * 0.9,
      dash: curve.dash.map((d) => d * theme.sizes.line * 0.6),
    });
    painter.screenLabel(
      curve.name + (entry.missing ? ' (not drawn)' : ''),
      left + sample + size * 0.5,
      y,
      {
        size,
        color: entry.missing ? theme.muted : theme.ink,
      },
    );
    y += lineHeight;
  }
  return y;
}

function measure(painter: Painter, text: string, size: number): number {
  const c = painter.ctx;
  c.save();
  c.font = `${size}px ${painter.theme.fontFamily}`;
  const width = c.measureText(text).width;
  c.restore();
  return width;
}

/**
 * Ticks across the road at p̄ = 0, ¼, ½, …: long at whole p̄ (the villages),
 * short between. Equal steps of p̄ are unequal steps of road: the parameter
 * runs fast on long segments.
 */
export function drawParameterTicks(painter: Painter, pieces: readonly Point[][]): void {
  const { theme, view } = painter;
  const major = view.worldLength(theme.sizes.curve * 2.4);
  const minor = view.worldLength(theme.sizes.curve * 1.7);
  const style = { color: theme.ink, width: Math.max(1.5, theme.sizes.thin * 1.5) };
  pieces.forEach((piece, i) => {
    for (let q = i === 0 ? 0 : 1; q <= 4; q++) {
      const t = q / 4;
      const p = bezierPoint(piece, t);
      const d = bezierTangent(piece, t);
      const speed = Math.hypot(d[0], d[1]);
      if (!(speed > 0)) continue;
      const length = q % 4 === 0 ? major : minor;
      const nx = (-d[1] / speed) * length;
      const ny = (d[0] / speed) * length;
      painter.segment([p[0] - nx, p[1] - ny], [p[0] + nx, p[1] + ny], style);
    }
  });
}

/**
 * The curvature comb: at samples along each piece a tooth along the normal,
 * as long as the curvature (scaled by the size of the map), and the line
 * through the tips. A jump of the comb at a village is a jump of curvature:
 * C¹ but not C².
 */
export function drawCurvatureComb(
  painter: Painter,
  pieces: readonly Point[][],
  scale: number,
  color: string,
): void {
  const samples = pieces.length > 100 ? 6 : 16;
  const teeth: number[] = [];
  let envelope: number[] = [];
  const flush = () => {
    painter.polylineFlat(envelope, { color, width: painter.theme.sizes.line });
    envelope = [];
  };
  pieces.forEach((piece) => {
    for (let j = 0; j <= samples; j++) {
      let frame;
      try {
        frame = bezierFrenetFrame(piece, j / samples);
      } catch {
        // Zero speed (two villages on one spot): no direction, so no tooth here.
        flush();
        continue;
      }
      const length = Math.max(-1.5, Math.min(1.5, -frame.curvature * scale)) * scale;
      const tip = [
        frame.point[0] + frame.normal[0] * length,
        frame.point[1] + frame.normal[1] * length,
      ];
      // Out to the tip and back, so one path draws every tooth.
      teeth.push(frame.point[0], frame.point[1], tip[0], tip[1], frame.point[0], frame.point[1]);
      envelope.push(tip[0], tip[1]);
    }
    // Each piece has its own envelope: a step between pieces is the point.
    flush();
  });
  painter.polylineFlat(teeth, { color, width: Math.max(1, painter.theme.sizes.thin), alpha: 0.7 });
}

/** Boxed sentences at the top of the figure (wrapped to its width): why something looks as it does. */
export function drawFigureNote(painter: Painter, lines: readonly string[], top?: number): void {
  let y = top;
  for (const line of lines) y = painter.note(line, { top: y });
}
