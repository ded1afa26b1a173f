/**
 * The last three scenes: segments to pixels (one segment stepped, then every
 * segment), anti-aliasing, and what zooming does to a fixed polyline.
 */
import { count } from '../../app/fields';
import { texNumber } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import type { RasterModel } from './model';
import { type Reveal, pixelPresses, pixelsAt } from './reveals';
import { type RasterState, segmentsOf } from './state';
import { ZOOM_PRESSES, zoomAt, zoomWords } from './zoomView';

const num = (v: number, digits = 2) => texNumber(v, digits);

/** Segments to pixels: one segment lit pixel by pixel (in chunks), then the whole polyline. */
export const pixelsScript = script<RasterState, RasterModel, Reveal>(
  step(
    'raster',
    ({ model: m }) =>
      `${m.size.width} × ${m.size.height} pixels and the ${count(m.adaptive.points.length - 1, 'segment')} to draw on them.`,
  ),
  step('ends', ({ model: m }) => {
    const { line } = m;
    const [a, b] = [line.first, line.last];
    const listed =
      line.count > line.pixels.length
        ? ` It lights ${line.count} pixels; the first ${line.pixels.length} are stepped through.`
        : '';
    return `Segment ${m.segment + 1}: its ends rounded to the pixels (${a[0]}, ${a[1]}) and (${b[0]}, ${b[1]}).${listed}`;
  }),
  repeat(
    'pixels',
    pixelPresses,
    ({ model: { line }, index }) => {
      const total = line.pixels.length;
      const shown = pixelsAt(total, index);
      const last = line.pixels[shown - 1];
      const axis = line.major;
      return `Step along ${axis} one pixel at a time, take the nearest ${axis === 'x' ? 'row' : 'column'}: ${shown} of ${total} pixels, the last (${last[0]}, ${last[1]}).`;
    },
    ({ model: { line }, index }) => {
      const i = pixelsAt(line.pixels.length, index) - 1;
      const [x, y] = line.pixels[i];
      return line.major === 'x'
        ? `x = ${x}:\\ y = ${num(line.ideal[i])} \\to ${y}`
        : `y = ${y}:\\ x = ${num(line.ideal[i])} \\to ${x}`;
    },
  ),
  step(
    'everySegment',
    ({ model: m }) =>
      `Every segment drawn the same way: ${count(m.pixels.size, 'pixel')} make the curve.`,
  ),
);

/** Anti-aliasing: a strip one pixel wide, each pixel shaded by the share it covers. */
export const coverageScript = script<RasterState, RasterModel, Reveal>(
  step(
    'strip',
    ({ model: m }) => `Anti-aliasing: draw segment ${m.segment + 1} as a strip one pixel wide.`,
  ),
  step(
    'shares',
    'Each pixel gets the share of its area the strip covers: 1 is full ink, 0 none.',
    () => `\\text{grey} = \\frac{\\text{area of pixel} \\cap \\text{strip}}{\\text{area of pixel}}`,
  ),
  step(
    'shades',
    ({ model: m }) =>
      `The whole curve: ${count(m.coverage?.size ?? 0, 'pixel')} in shades instead of ${m.pixels.size} on or off.`,
  ),
);

/** Zoom in, zoom out: the same n segments stray more pixels the more the screen magnifies. */
export const zoomScript = script<RasterState, RasterModel, Reveal>(
  repeat(
    'zoom',
    () => ZOOM_PRESSES,
    ({ state, model: m, index }) => {
      const zoom = m.zoom;
      if (!zoom) return '';
      const gap = m.uniform.deviation.distance * zoom.size.zoom;
      const adaptive = zoom.adaptive.length - 1;
      const verdict =
        zoom.uniformFar.length === 0
          ? 'every lit pixel within 1 px of the curve'
          : `${count(zoom.uniformFar.length, 'pixel')} lit more than 1 px off the curve`;
      return `Zoom ×${zoomWords(zoomAt(index))}, the curve on ${zoom.full.width} × ${zoom.full.height} pixels: ${count(segmentsOf(state), 'segment')} ${segmentsOf(state) === 1 ? 'strays' : 'stray'} ${num(gap)} px; in the 32 × 24 window, ${verdict}. Adaptive to ${num(state.tolerance)} px: ${count(adaptive, 'segment')}.`;
    },
    ({ model: m }) => {
      const zoom = m.zoom;
      if (!zoom) return null;
      const distance = m.uniform.deviation.distance;
      return `${num(distance, 3)}\\ \\text{units} \\times ${zoom.size.zoom} \\tfrac{\\text{px}}{\\text{unit}} = ${num(distance * zoom.size.zoom)}\\ \\text{px}`;
    },
  ),
);
