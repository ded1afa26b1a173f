import {
  type ArcLengthRow,
  type Point,
  bezierArcLength,
  bezierArcLengthTable,
  bezierParameterAtLength,
  bezierPoint,
  bezierTangent,
} from '../../math';

const PLOT_SAMPLES = 100;

export interface ArcModel {
  /** The whole length L. */
  length: number;
  /** s at t = i/n (the table). */
  table: ArcLengthRow[];
  /** t at s = kL/n: equal steps of arc length. */
  equal: ArcLengthRow[];
  /** Points at equal steps of t, and at equal steps of s. */
  byT: Point[];
  byS: Point[];
  /** Unit tangents there (to draw the ticks across the curve); [1, 0] where the speed is 0. */
  byTDirection: Point[];
  bySDirection: Point[];
  /** s(t) sampled, interleaved t, s. */
  plot: Float64Array;
  /** P(t) at the plot's samples. */
  plotPoints: Point[];
  /** s at the cursor t. */
  sAtT: number;
}

/** Everything of the arc length model that does not depend on the cursor t: computed once per curve and n. */
export type ArcCurve = Omit<ArcModel, 'sAtT'>;

/** The arc length model at the cursor t: the table reused, only s(t) new. */
export function deriveArc(curve: ArcCurve, p: readonly Point[], t: number): ArcModel {
  return { ...curve, sAtT: bezierArcLength(p, t) };
}

export function deriveArcCurve(p: readonly Point[], n: number): ArcCurve {
  const table = bezierArcLengthTable(p, n);
  const length = table[n].s;
  const equal = table.map((_, k) => {
    const s = (k * length) / n;
    return { s, t: k === n ? 1 : bezierParameterAtLength(p, s) };
  });
  const plot = new Float64Array(2 * (PLOT_SAMPLES + 1));
  for (let i = 0; i <= PLOT_SAMPLES; i++) {
    plot[2 * i] = i / PLOT_SAMPLES;
    plot[2 * i + 1] = bezierArcLength(p, i / PLOT_SAMPLES);
  }
  return {
    length,
    table,
    equal,
    byT: table.map((row) => bezierPoint(p, row.t)),
    byS: equal.map((row) => bezierPoint(p, row.t)),
    byTDirection: table.map((row) => direction(p, row.t)),
    bySDirection: equal.map((row) => direction(p, row.t)),
    plot,
    plotPoints: Array.from({ length: PLOT_SAMPLES + 1 }, (_, i) =>
      bezierPoint(p, i / PLOT_SAMPLES),
    ),
  };
}

function direction(p: readonly Point[], t: number): Point {
  const v = bezierTangent(p, t);
  const length = Math.hypot(v[0], v[1]);
  return length > 0 ? [v[0] / length, v[1] / length] : [1, 0];
}
