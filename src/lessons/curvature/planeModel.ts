import {
  type Circle,
  type Point,
  bezierCurvature,
  bezierDerivative,
  bezierFrenetFrame,
  bezierPoint,
  bezierInflections,
  bezierTangent,
  norm,
  osculatingCircle,
  sampleBezier,
} from '../../math';
import { robustCap, runs, sizeOf } from './measure';
import type { PiecewiseCurve } from './sources';

/** Below this |κ| times the size of the control polygon, κ counts as 0. */
const FLAT = 1e-9;
/** Samples of the plot and teeth of the comb along the whole curve (at least 12 and 4 per piece). */
const PLOT_SAMPLES = 240;
const COMB_TEETH = 64;
const CURVE_SAMPLES = 160;

/** What the plane curve has at the cursor t; null where it is undefined (`why` says why). */
export interface PlaneAt {
  t: number;
  /**
   * The global parameter p̄ = pieces·t (the lecture slides' p̄; `s` here), its
   * piece i and the local parameter p = p̄ − i (`u` here). P′ and P″ are taken
   * in p, which is the same as in p̄.
   */
  s: number;
  piece: number;
  u: number;
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
  /** The same in a few words, for a figure too small to hold the whole clear of its points. */
  brief: string | null;
}

export interface PlaneModel {
  /** The curve sampled, interleaved x, y. */
  curve: Float64Array;
  /** The pieces (one for a single Bézier curve), their joins, and what the source could not take. */
  pieces: PiecewiseCurve;
  /** Extent of the control polygon: scales arrows and comb teeth. */
  size: number;
  at: PlaneAt;
  /**
   * Comb teeth [base, tip] in runs: tip = P − c·κ·(T turned left), on the
   * outside of the bend; c = combScale. A run ends where a tooth would be too long.
   */
  comb: [Point, Point][][];
  combScale: number;
  /** κ and |P′| against the global p̄ for the plot, cut where undefined and at every join (interleaved p̄, value). */
  kappa: Float64Array[];
  speed: Float64Array[];
  /** |κ| above which the plot and comb clip (huge near a cusp). */
  kappaCap: number;
  /** The global p̄ of the inflections (κ = 0) and cusps (P′ = 0), ends and joins exactly whole numbers. */
  inflections: number[];
  cusps: number[];
  /** Where they are on the curve (t is the global p̄). */
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

/** The global p̄ = pieces·t ∈ [0, pieces] (`s`), its piece and its local parameter p = p̄ − i (`u`), as in the lecture slides. */
export function locate(pieces: number, t: number): { s: number; piece: number; u: number } {
  const s = pieces * t;
  const piece = Math.min(Math.floor(s), pieces - 1);
  return { s, piece, u: s - piece };
}

function planeAt(segments: readonly Point[][], t: number, size: number): PlaneAt {
  const where = locate(segments.length, t);
  const p = segments[where.piece];
  const u = where.u;
  const point = bezierPoint(p, u);
  const velocity = bezierTangent(p, u);
  const acceleration = p.length > 2 ? bezierTangent(bezierDerivative(p), u) : point.map(() => 0);
  const speed = norm(velocity);
  const base = { t, ...where, point, velocity, acceleration, speed };
  const curvature = curvatureOrNull(p, u);
  if (curvature === null) {
    return {
      ...base,
      tangent: null,
      normal: null,
      curvature: null,
      circle: null,
      why: `Cusp: P′(t) = 0, the curve stops and turns back. T = P′/|P′| divides by 0: T, N, κ and the osculating circle are undefined.`,
      brief: 'Cusp: P′(t) = 0, so T, N and κ are undefined',
    };
  }
  const frame = bezierFrenetFrame(p, u);
  if (Math.abs(curvature) * size <= FLAT) {
    return {
      ...base,
      tangent: frame.tangent,
      normal: null,
      curvature: 0,
      circle: null,
      // At an end (a natural spline's P″ = 0) the curve only ends straight: no far side to turn to.
      why:
        where.s === 0 || where.s === segments.length
          ? `κ = 0 at the end: the curve ends straight. The osculating circle’s radius 1/κ is infinite; N, towards its centre, is undefined.`
          : `Inflection: κ = 0, straight for an instant. The osculating circle’s radius 1/κ is infinite; N, towards its centre, is undefined and changes side here.`,
      brief:
        where.s === 0 || where.s === segments.length
          ? 'κ = 0 at the end: N is undefined'
          : 'Inflection: κ = 0, N is undefined',
    };
  }
  const side = Math.sign(curvature);
  return {
    ...base,
    tangent: frame.tangent,
    normal: frame.normal.map((v) => side * v),
    curvature,
    circle: osculatingCircle(p, u),
    why: null,
    brief: null,
  };
}

/** Everything of the plane model that does not depend on the cursor t: computed once per curve. */
export type PlaneCurve = Omit<PlaneModel, 'at'>;

/** The plane model at the cursor t: the curve's part reused, only P(t) and its frame new. */
export function derivePlane(curve: PlaneCurve, t: number): PlaneModel {
  return { ...curve, at: planeAt(curve.pieces.segments, t, curve.size) };
}

export function deriveCurve(pieces: PiecewiseCurve): PlaneCurve {
  const { segments } = pieces;
  const m = segments.length;
  const size = sizeOf(segments.flat());
  const perPiece = (total: number, least: number) => Math.max(least, Math.ceil(total / m));
  const samples = perPiece(PLOT_SAMPLES, 12);
  const teeth = perPiece(COMB_TEETH, 4);
  // κ per piece: the plot's runs are cut at every join, so a jump of κ shows as a step.
  const values = segments.map((p) =>
    Array.from({ length: samples + 1 }, (_, k) => curvatureOrNull(p, k / samples)),
  );
  // A robust scale for κ: a cusp sends |κ| to infinity, so take the 90th percentile.
  const kappaCap = Math.max(robustCap(values.flat()), 1e-9 / size);
  const shift = (run: Float64Array, i: number) => run.map((v, k) => (k % 2 === 0 ? v + i : v));
  const kappa = values.flatMap((row, i) =>
    runs(row.map((v) => (v !== null && Math.abs(v) <= 1.25 * kappaCap ? v : null))).map((run) =>
      shift(run, i),
    ),
  );
  const speed = segments.map((p, i) => {
    const run = new Float64Array(2 * (samples + 1));
    for (let k = 0; k <= samples; k++) {
      run[2 * k] = i + k / samples;
      run[2 * k + 1] = norm(bezierTangent(p, k / samples));
    }
    return run;
  });

  const combScale = (0.3 * size) / kappaCap;
  // Teeth too long to draw (near a cusp |κ| → ∞) are left out, and the line
  // through the tips is broken there and at every join.
  const comb: [Point, Point][][] = [];
  for (const p of segments) {
    let run: [Point, Point][] = [];
    for (let k = 0; k <= teeth; k++) {
      const u = k / teeth;
      const kappaHere = curvatureOrNull(p, u);
      if (kappaHere === null || Math.abs(kappaHere) > 1.25 * kappaCap) {
        if (run.length) comb.push(run);
        run = [];
        continue;
      }
      const frame = bezierFrenetFrame(p, u);
      run.push([
        frame.point,
        frame.point.map((v, d) => v - combScale * kappaHere * frame.normal[d]),
      ]);
    }
    if (run.length) comb.push(run);
  }
  const cusps = unique(
    segments.flatMap((p, i) => (p.length === 4 ? cuspParameters(p) : []).map((u) => i + u)),
  );
  // At a cusp the curve turns back with κ → ±∞ on both sides: it is not an inflection.
  const inflections = unique(
    segments.flatMap((p, i) => bezierInflections(p).map((u) => i + u)),
  ).filter((s) => cusps.every((c) => Math.abs(c - s) > 1e-9));
  const pointAt = (s: number) => {
    const where = locate(m, s / m);
    return bezierPoint(segments[where.piece], where.u);
  };
  const curve = new Float64Array(2 * m * perPiece(CURVE_SAMPLES, 16) + 2);
  const pieceSamples = perPiece(CURVE_SAMPLES, 16);
  segments.forEach((p, i) => curve.set(sampleBezier(p, pieceSamples), 2 * i * pieceSamples));
  return {
    curve,
    pieces,
    size,
    comb,
    combScale,
    kappa,
    speed,
    kappaCap,
    inflections,
    cusps,
    marks: [
      ...inflections.map((s) => ({ t: s, point: pointAt(s), kind: 'inflection' as const })),
      ...cusps.map((s) => ({ t: s, point: pointAt(s), kind: 'cusp' as const })),
    ],
  };
}

/**
 * Sorted, with values closer than 1e-9 (the same join seen from both pieces)
 * taken once, and a value within 1e-9 of a whole number (an end or a join) put
 * on it: a root found at 2.7·10⁻¹⁶ is the end p̄ = 0.
 */
function unique(values: number[]): number[] {
  const snapped = values.map((v) => (Math.abs(v - Math.round(v)) <= 1e-9 ? Math.round(v) : v));
  const sorted = snapped.sort((a, b) => a - b);
  return sorted.filter((v, i) => i === 0 || v - sorted[i - 1] > 1e-9);
}
