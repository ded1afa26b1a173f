/**
 * Cubic Bézier segments on screen: exact curves through an affine view, cut
 * to the clip rectangle, or 48 chords through a perspective one; and each
 * one's ink as 12 chords, sampled by the maths, for the labels to keep off.
 */
import { bezierPoint, samplePlanarCubic } from '../math';
import { clipCubic, clipPolyline } from './clip';
import type { P, Painter, StrokeStyle } from './painter';

/**
 * Cubic Bézier segments, each 4 control points. An affine projection keeps a
 * Bézier a Bézier, so the screen path is exact; under perspective the
 * segments are flattened.
 */
export function drawCubicSegments(
  painter: Painter,
  segments: readonly (readonly P[])[],
  style: StrokeStyle = {},
): void {
  if (!segments.length || painter.hidden(style)) return;
  const c = painter.ctx;
  c.save();
  painter.applyStroke(style, painter.sizes.curve, painter.theme.curve);
  c.beginPath();
  let pen: [number, number] | null = null;
  let drawn = false;
  const q = new Array<number>(8);
  const from = painter.ink.segments;
  for (const seg of segments) {
    if (!painter.view.affine) {
      drawn = flattenedCubic(painter, seg, (style.width ?? painter.sizes.curve) / 2) || drawn;
      pen = null;
      continue;
    }
    for (let k = 0; k < 4; k++) {
      const [x, y] = painter.view.toScreen(seg[k]);
      q[2 * k] = x;
      q[2 * k + 1] = y;
    }
    if (!q.every(Number.isFinite)) {
      pen = null;
      continue;
    }
    const end = clipCubic(q, painter.clip, c, pen);
    if (end) drawn = true;
    pen = end;
    inkCubic(painter, q, (style.width ?? painter.sizes.curve) / 2);
  }
  if (drawn) c.stroke();
  c.restore();
  if (style.role === 'curve') painter.ink.subject(from);
}

/** A cubic seen through a projection that bends lines (perspective): drawn as 48 chords. */
function flattenedCubic(painter: Painter, seg: readonly P[], half: number): boolean {
  // A segment with a coordinate that is not a number draws nothing (the maths would refuse it).
  if (!seg.every((p) => p.every(Number.isFinite))) return false;
  const samples: P[] = [];
  for (let i = 0; i <= 48; i++) samples.push(bezierPoint(seg, i / 48));
  const xy = painter.project(samples);
  painter.ink.polyline(xy, half);
  return clipPolyline(xy, painter.clip, painter.ctx) > 0;
}

/** A screen cubic's 13 samples (x, y): reused, for its ink is found on every drag frame. */
const chordEnds = new Float64Array(26);

/** A screen cubic's ink, as 12 chords (within a pixel or so of the curve at figure sizes). */
function inkCubic(painter: Painter, q: readonly number[], half: number): void {
  const xy = samplePlanarCubic(q, 12, chordEnds);
  for (let i = 2; i <= 24; i += 2)
    painter.ink.segment(xy[i - 2], xy[i - 1], xy[i], xy[i + 1], half);
}
