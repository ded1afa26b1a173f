import type { DrawInfo, LessonApi } from '../../app/lesson';
import { sampleBezier } from '../../math';
import type { Painter, StrokeStyle } from '../../render/painter';
import type { ExperimentId, PropertiesState } from './state';

/** One named experiment: what it shows, how it draws, what the panel says about it. */
export interface Experiment {
  id: ExperimentId;
  /** Short name, as in the list of properties. */
  title: string;
  /** The one sentence of explanation. */
  sentence: string;
  /** Extra points the view must show besides the control points (arrow tips, images). */
  extent?(state: PropertiesState): readonly (readonly number[])[];
  draw(painter: Painter, state: PropertiesState, info: DrawInfo): void;
  /** The live details for the panel: formulas with the numbers, measurements. */
  explain(state: PropertiesState, api: LessonApi<PropertiesState>): Node[];
}

/** Samples enough for a smooth curve of degree n. */
export const samplesFor = (n: number) => Math.max(96, 24 * n);

/** The Bézier curve of `points`, sampled and drawn. */
export function drawBezier(
  painter: Painter,
  points: readonly (readonly number[])[],
  style: StrokeStyle = {},
): void {
  painter.polylineFlat(sampleBezier(points, samplesFor(points.length - 1)), style);
}

/** The control polygon, dashed. */
export function drawPolygon(
  painter: Painter,
  points: readonly (readonly number[])[],
  style: StrokeStyle = {},
): void {
  painter.polyline(points, {
    color: painter.theme.polygon,
    width: painter.theme.sizes.line,
    dash: [6, 5],
    ...style,
  });
}

/** A point on the curve with a label, skipped in thumbnails. */
export function drawMarked(
  painter: Painter,
  point: readonly number[],
  text: string,
  info: DrawInfo,
  color = painter.theme.accent,
): void {
  painter.dot(point, color, painter.theme.sizes.point * 1.3);
  if (info.thumbnail) return;
  painter.label(text, point, {
    dx: painter.theme.sizes.point + 5,
    dy: painter.theme.sizes.label * 0.9,
    color,
    halo: true,
    bold: true,
  });
}

/** t as typed: up to four decimals, trailing zeros dropped. */
export const texT = (t: number) => String(Number(t.toFixed(4)));
