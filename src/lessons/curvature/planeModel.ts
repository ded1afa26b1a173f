import {
  type Circle,
  type Point,
  bezierCurvature,
  bezierDerivative,
  bezierFrenetFrame,
  bezierPoint,
  bezierTangent,
  cubicInflections,
  norm,
  osculatingCircle,
  sampleBezier,
} from '../../math';
import { robustCap, runs, sizeOf } from './measure';

/** Below this |κ| times the size of the control polygon, κ counts as 0. */
const FLAT = 1e-9;
const PLOT_SAMPLES = 240;
const COMB_TEETH = 64;

/** What the plane curve has at the cursor t; null where it is undefined (`why` says why). */
export interface PlaneAt {
  t: number;
  point: Point;
  velocity: Point;
  acceleration: Point;
  speed: number;
  tangent: Point | null;
  /** The principal normal: perpendicular to T, towards the centre of curvature. */
  normal: Point | null;
  /** Signed curvature (positive turning left), null at a cusp. */
  curvature: number | null;
  circle: Circle | null;
  why: string | null;
}

export interface PlaneModel {
  /** The curve sampled, interleaved x, y. */
  curve: Float64Array;
  /** Extent of the control polygon: scales arrows and comb teeth. */
  size: number;
  at: PlaneAt;
  /**
   * Comb teeth [base, tip] in runs: tip = P − c·κ·(T turned left), on the
   * outside of the bend; c = combScale. A run ends where a tooth would be too long.
   */
  comb: [Point, Point][][];
  combScale: number;
  /** κ(t) and |P′(t)| for the plot, cut where undefined (interleaved t, value). */
  kappa: Float64Array[];
  speed: Float64Array;
  /** |κ| above which the plot and comb clip (huge near a cusp). */
  kappaCap: number;
  inflections: number[];
  cusps: number[];
  /** Where they are on the curve. */
  marks: { t: number; point: Point; kind: 'inflection' | 'cusp' }[];
}

/** The parameters in [0, 1] where the cubic's velocity P′ vanishes (both components of the hodograph). */
export function cuspParameters(p: readonly Point[]): number[] {
  const h = bezierDerivative(p);
  // Each coordinate of P′ is a quadratic: a t² + b t + c in power form.
  const coefficients = (d: number) => [
    h[0][d] - 2 * h[1][d] + h[2][d],
    2 * (h[1][d] - h[0][d]),
    h[0][d],
  ];
  const size = sizeOf(p);
  const roots = (d: number): number[] => {
    const [a, b, c] = coefficients(d);
    if (Math.abs(a) <= 1e-12 * size) return Math.abs(b) <= 1e-12 * size ? [] : [-c / b];
    const discriminant = b * b - 4 * a * c;
    if (discriminant < -1e-12 * size * size) return [];
    const root = Math.sqrt(Math.max(0, discriminant));
    return [(-b - root) / (2 * a), (-b + root) / (2 * a)];
  };
  const candidates = [...roots(0), ...roots(1)].filter((t) => t >= 0 && t <= 1);
  const cusps = candidates.filter((t) => norm(bezierDerivativeAt(h, t)) <= 1e-9 * size);
  return [...new Set(cusps.map((t) => Number(t.toPrecision(12))))].sort((x, y) => x - y);
}

function bezierDerivativeAt(h: readonly Point[], t: number): Point {
  return bezierPoint(h, t);
}

/** Signed κ at t, or null where the speed is zero. */
function curvatureOrNull(p: readonly Point[], t: number): number | null {
  try {
    return bezierCurvature(p, t);
  } catch {
    return null;
  }
}

function planeAt(p: readonly Point[], t: number, size: number): PlaneAt {
  const point = bezierPoint(p, t);
  const velocity = bezierTangent(p, t);
  const acceleration = bezierTangent(bezierDerivative(p), t);
  const speed = norm(velocity);
  const base = { t, point, velocity, acceleration, speed };
  const curvature = curvatureOrNull(p, t);
  if (curvature === null) {
    return {
      ...base,
      tangent: null,
      normal: null,
      curvature: null,
      circle: null,
      why: `Cusp: P′(t) = 0, the curve stops here and turns back. T = P′/|P′| divides by 0, so T, N, κ and the osculating circle are undefined.`,
    };
  }
  const frame = bezierFrenetFrame(p, t);
  if (Math.abs(curvature) * size <= FLAT) {
    return {
      ...base,
      tangent: frame.tangent,
      normal: null,
      curvature: 0,
      circle: null,
      why: `Inflection: κ = 0, the curve is straight for an instant. The osculating circle's radius 1/κ is infinite and N, which points to its centre, is undefined; on either side N points to opposite sides.`,
    };
  }
  const side = Math.sign(curvature);
  return {
    ...base,
    tangent: frame.tangent,
    normal: frame.normal.map((v) => side * v),
    curvature,
    circle: osculatingCircle(p, t),
    why: null,
  };
}

export function derivePlane(p: readonly Point[], t: number): PlaneModel {
  const size = sizeOf(p);
  const values: (number | null)[] = [];
  const speed = new Float64Array(2 * (PLOT_SAMPLES + 1));
  for (let i = 0; i <= PLOT_SAMPLES; i++) {
    const u = i / PLOT_SAMPLES;
    values.push(curvatureOrNull(p, u));
    speed[2 * i] = u;
    speed[2 * i + 1] = norm(bezierTangent(p, u));
  }
  // A robust scale for κ: a cusp sends |κ| to infinity, so take the 90th percentile.
  const kappaCap = Math.max(robustCap(values), 1e-9 / size);
  // Runs of κ(t) for the plot, cut where it is undefined or leaves the plot (±1.25 cap).
  const kappa = runs(values.map((v) => (v !== null && Math.abs(v) <= 1.25 * kappaCap ? v : null)));

  const combScale = (0.3 * size) / kappaCap;
  // Teeth too long to draw (near a cusp |κ| → ∞) are left out, and the line
  // through the tips is broken there.
  const comb: [Point, Point][][] = [];
  let run: [Point, Point][] = [];
  for (let i = 0; i <= COMB_TEETH; i++) {
    const u = i / COMB_TEETH;
    const k = curvatureOrNull(p, u);
    if (k === null || Math.abs(k) > 1.25 * kappaCap) {
      if (run.length) comb.push(run);
      run = [];
      continue;
    }
    const frame = bezierFrenetFrame(p, u);
    run.push([frame.point, frame.point.map((v, d) => v - combScale * k * frame.normal[d])]);
  }
  if (run.length) comb.push(run);
  const cusps = cuspParameters(p);
  // At a cusp the curve turns back with κ → ±∞ on both sides: it is not an inflection.
  const inflections = cubicInflections(p).filter((u) => cusps.every((c) => Math.abs(c - u) > 1e-9));
  return {
    curve: sampleBezier(p, 160),
    size,
    at: planeAt(p, t, size),
    comb,
    combScale,
    kappa,
    speed,
    kappaCap,
    inflections,
    cusps,
    marks: [
      ...inflections.map((u) => ({ t: u, point: bezierPoint(p, u), kind: 'inflection' as const })),
      ...cusps.map((u) => ({ t: u, point: bezierPoint(p, u), kind: 'cusp' as const })),
    ],
  };
}
