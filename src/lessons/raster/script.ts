import type { Scene, StepsSpec } from '../../app/lesson';
import { flattenBezier } from '../../math';
import { texNumber } from '../../render/formula';
import { type RasterModel, SAME_ERROR_MAX, derive, instructiveSegment, zoomAtStep } from './model';
import { type RasterState, type View, segmentsOf } from './state';

/** Pixel steps of one segment are shown in at most this many clicks. */
export const LINE_CHUNKS = 12;
/** The pieces of the flattening are shown in at most this many clicks. */
export const TREE_CHUNKS = 20;

const num = (v: number, digits = 2) => texNumber(v, digits);
const px = (m: RasterModel, units: number) => units * m.state.z;
const plural = (count: number, word: string) => `${count} ${word}${count === 1 ? '' : 's'}`;

/** The steps of each scene, the last showing it all. */
export function stepCount(state: RasterState): number {
  switch (state.x) {
    case 'plot':
    case 'compare':
    case 'zoom':
      return 4;
    case 'coverage':
      return 2;
    case 'subdivide':
      return Math.min(TREE_CHUNKS, derive(state).tree.length);
    case 'pixels':
      return 2 + Math.min(LINE_CHUNKS, derive(state).line.pixels.length);
  }
}

/** How many pieces of the flattening are visited by step k. */
export function piecesShown(m: RasterModel, k: number): number {
  const count = stepCount(m.state);
  return k >= count ? m.tree.length : Math.ceil((m.tree.length * k) / count);
}

/** How many pixels of the stepped segment are lit by step k of the pixel scene. */
export function pixelsShown(m: RasterModel, k: number): number {
  const total = m.line.pixels.length;
  const chunks = Math.min(LINE_CHUNKS, total);
  if (k <= 1) return 0;
  return Math.min(total, Math.ceil((total * (k - 1)) / chunks));
}

function describePlot(m: RasterModel, k: number): string {
  const n = segmentsOf(m.state);
  const d = m.uniform.deviation;
  switch (k) {
    case 0:
      return `Given: the ${m.state.p.length} control points of a curve of degree ${m.degree}. Task: plot the curve.`;
    case 1:
      return `Compute ${n + 1} points P(k/${n}) on the curve, k = 0 … ${n}: the only exact points we will have.`;
    case 2:
      return `Join them by ${plural(n, 'straight segment')}: this polyline is what the screen draws.`;
    case 3:
      return 'The true curve: between the computed points it bends away from the segments.';
    default:
      return `Largest gap ${num(px(m, d.distance))} px, at t = ${num(d.t, 3)} in segment ${d.piece + 1} of ${n}.`;
  }
}

function describeCompare(m: RasterModel, k: number): string {
  const tol = num(m.state.tol);
  const n = segmentsOf(m.state);
  const a = m.adaptive;
  const same = m.sameError;
  switch (k) {
    case 0:
      return `The same curve twice: uniform sampling on the left, adaptive flattening to τ = ${tol} px on the right.`;
    case 1:
      return `Uniform, ${plural(n, 'segment')}: largest gap ${num(px(m, m.uniform.deviation.distance))} px (τ = ${tol} px).`;
    case 2:
      return `Adaptive to τ = ${tol} px: ${plural(a.points.length - 1, 'segment')}, largest gap ${num(px(m, a.deviation.distance))} px, short ones only in the bend.`;
    case 3:
      return `For the same gap of ${num(px(m, a.deviation.distance))} px, uniform sampling needs ${same ? plural(same.points.length - 1, 'segment') : `more than ${SAME_ERROR_MAX} segments`}.`;
    default:
      return `Without measuring, uniform sampling must plan for the sharpest bend: ${plural(m.boundCount, 'segment')} to be sure of τ.`;
  }
}

function describeSubdivide(m: RasterModel, k: number): string {
  const shown = piecesShown(m, k);
  if (shown === 0)
    return `Is the control polygon within τ = ${num(m.state.tol)} px of a straight line? If not, split at t = ½.`;
  if (shown === m.tree.length) {
    return `Done: ${plural(m.adaptive.points.length - 1, 'segment')} from ${plural(m.tree.length, 'piece')} looked at; the tree is ${Math.max(...m.tree.map((n) => n.depth))} levels deep.`;
  }
  const node = m.tree[shown - 1];
  const range = `t ∈ [${num(node.t0, 3)}, ${num(node.t1, 3)}]`;
  const flatness = num(px(m, node.flatness));
  return node.split
    ? `Piece ${range}: flatness ${flatness} px > τ, so split it at its middle.`
    : `Piece ${range}: flatness ${flatness} px ≤ τ, so draw it as one segment.`;
}

function describePixels(m: RasterModel, k: number): string {
  const count = stepCount(m.state);
  const { line } = m;
  const total = line.pixels.length;
  const segment = m.segment + 1;
  if (k === 0)
    return `${m.size.width} × ${m.size.height} pixels and the ${plural(m.adaptive.points.length - 1, 'segment')} to draw on them.`;
  if (k === 1) {
    const [a, b] = [line.first, line.last];
    const listed =
      line.count > total
        ? ` It lights ${line.count} pixels; the first ${total} are stepped through.`
        : '';
    return `Segment ${segment}: its ends rounded to the pixels (${a[0]}, ${a[1]}) and (${b[0]}, ${b[1]}).${listed}`;
  }
  if (k === count)
    return `Every segment drawn the same way: ${plural(m.pixels.size, 'pixel')} make the curve.`;
  const shown = pixelsShown(m, k);
  const last = line.pixels[shown - 1];
  const axis = line.major;
  return `Step along ${axis} one pixel at a time, take the nearest ${axis === 'x' ? 'row' : 'column'}: ${shown} of ${total} pixels, the last (${last[0]}, ${last[1]}).`;
}

function describeCoverage(m: RasterModel, k: number): string {
  switch (k) {
    case 0:
      return `Anti-aliasing: draw segment ${m.segment + 1} as a strip one pixel wide.`;
    case 1:
      return 'Each pixel gets the share of its area the strip covers: 1 is full ink, 0 none.';
    default:
      return `The whole curve: ${plural(m.coverage?.size ?? 0, 'pixel')} in shades instead of ${m.pixels.size} on or off.`;
  }
}

function describeZoom(m: RasterModel, k: number): string {
  const zoom = m.zoom;
  if (!zoom) return '';
  const n = segmentsOf(m.state);
  const gap = m.uniform.deviation.distance * zoom.size.zoom;
  const factor = k === 0 ? '½' : String(zoomAtStep(k));
  const adaptive = zoom.adaptive.length - 1;
  const verdict =
    zoom.uniformFar.length === 0
      ? 'every lit pixel within 1 px of the curve'
      : `${plural(zoom.uniformFar.length, 'pixel')} lit more than 1 px off the curve`;
  return `Zoom ×${factor}, the curve on ${zoom.full.width} × ${zoom.full.height} pixels: ${n} segments stray ${num(gap)} px, ${verdict}. Adaptive to ${num(m.state.tol)} px: ${adaptive} segments.`;
}

const DESCRIBE: Record<View, (m: RasterModel, k: number) => string> = {
  plot: describePlot,
  compare: describeCompare,
  subdivide: describeSubdivide,
  pixels: describePixels,
  coverage: describeCoverage,
  zoom: describeZoom,
};

function formula(m: RasterModel, state: RasterState): string | null {
  const k = state.step;
  const n = segmentsOf(state);
  switch (state.x) {
    case 'plot':
      if (k === 1) return `P\\!\\left(\\tfrac{k}{${n}}\\right),\\quad k = 0,1,\\dots,${n}`;
      if (k === 4)
        return `\\max_t \\operatorname{dist}\\big(P(t),\\ \\text{segment}\\big) = ${num(px(m, m.uniform.deviation.distance))}\\ \\text{px at } t = ${num(m.uniform.deviation.t, 3)}`;
      return null;
    case 'compare':
      if (k === 4)
        return `N = \\left\\lceil \\sqrt{\\tfrac{n(n-1)\\,\\max\\|\\Delta^2 P\\|}{8\\,\\tau}} \\right\\rceil = ${m.boundCount}`;
      if (k >= 2)
        return `\\text{uniform } ${n}: ${num(px(m, m.uniform.deviation.distance))}\\ \\text{px} \\qquad \\text{adaptive } ${m.adaptive.points.length - 1}: ${num(px(m, m.adaptive.deviation.distance))}\\ \\text{px} \\le \\tau = ${num(state.tol)}`;
      return null;
    case 'subdivide': {
      const shown = piecesShown(m, k);
      if (shown === 0 || shown === m.tree.length)
        return `\\tfrac{n(n-1)}{8}\\max_i \\|P_{i+2} - 2P_{i+1} + P_i\\| \\le \\tau = ${num(state.tol)}`;
      const node = m.tree[shown - 1];
      return `\\tfrac{${m.degree}\\cdot${m.degree - 1}}{8}\\max\\|\\Delta^2 P\\| = ${num(px(m, node.flatness))}\\ ${node.split ? '>' : '\\le'}\\ ${num(state.tol)}`;
    }
    case 'pixels': {
      const shown = pixelsShown(m, k);
      if (shown === 0 || k === stepCount(state)) return null;
      const i = shown - 1;
      const [x, y] = m.line.pixels[i];
      return m.line.major === 'x'
        ? `x = ${x}:\\ y = ${num(m.line.ideal[i])} \\to ${y}`
        : `y = ${y}:\\ x = ${num(m.line.ideal[i])} \\to ${x}`;
    }
    case 'coverage':
      return k === 1
        ? `\\text{grey} = \\frac{\\text{area of pixel} \\cap \\text{strip}}{\\text{area of pixel}}`
        : null;
    case 'zoom': {
      const zoom = m.zoom;
      if (!zoom) return null;
      return `${num(m.uniform.deviation.distance, 3)}\\ \\text{units} \\times ${zoom.size.zoom} \\tfrac{\\text{px}}{\\text{unit}} = ${num(m.uniform.deviation.distance * zoom.size.zoom)}\\ \\text{px}`;
    }
  }
}

export const steps: StepsSpec<RasterState, RasterModel> = {
  key: 'step',
  count: stepCount,
  describe: (state, k) =>
    DESCRIBE[state.x](derive(k === state.step ? state : { ...state, step: k }), k),
  formula,
};

/** A scene sets what the figures show and the lecture's numbers; the curve stays as it is. */
const scene = (
  id: View,
  label: string,
  change: (s: RasterState) => Partial<RasterState> = () => ({}),
): Scene<RasterState> => ({
  id,
  label,
  apply: (current) => {
    const next = { ...current, x: id, n: 6, tol: 0.5, z: 1, step: 0 };
    return { ...next, ...change(next) };
  },
});

/** The segment worth stepping through: the longest of the adaptive polyline. */
const longest = (s: RasterState) => ({
  seg: instructiveSegment(flattenBezier(s.p, s.tol / s.z), s.z),
});

export const scenes: Scene<RasterState>[] = [
  scene('plot', 'Plot the curve', () => ({ seg: 0 })),
  scene('compare', 'Uniform or adaptive'),
  scene('subdivide', 'Flatten by subdivision'),
  scene('pixels', 'Segments to pixels', longest),
  scene('coverage', 'Anti-aliasing', longest),
  scene('zoom', 'Zoom in, zoom out', () => ({ n: 4 })),
];
