import { type Point, bezierFrenetFrame, bezierPoint, bezierTangent } from '../../math';

// Marks along the road, as plain numbers for the map to draw: ticks across it
// at every quarter of p̄, and the curvature comb. Their lengths on screen are
// the map's business; where they stand and which way they point is found here.

/** Numbers per tick in `parameterTicks`: x, y, the unit normal's x and y, and 1 at a village (else 0). */
export const TICK_STRIDE = 5;

/**
 * Ticks across the road at p̄ = 0, ¼, ½, …: at whole p̄ (the villages) and in
 * between. Equal steps of p̄ are unequal steps of road: the parameter runs
 * fast on long segments. Where the road stops (zero speed) there is no tick.
 */
export function parameterTicks(pieces: readonly Point[][]): Float64Array {
  const ticks: number[] = [];
  pieces.forEach((piece, i) => {
    for (let q = i === 0 ? 0 : 1; q <= 4; q++) {
      const t = q / 4;
      const p = bezierPoint(piece, t);
      const d = bezierTangent(piece, t);
      const speed = Math.hypot(d[0], d[1]);
      if (!(speed > 0)) continue;
      ticks.push(p[0], p[1], -d[1] / speed, d[0] / speed, q % 4 === 0 ? 1 : 0);
    }
  });
  return Float64Array.from(ticks);
}

/** The curvature comb: teeth out to the tips and back (one path), and the line through the tips. */
export interface CurvatureComb {
  /** Interleaved x, y: base, tip, base for every tooth. */
  teeth: Float64Array;
  /** The line through the tips, one per piece (split where the road stops): a jump between them is a jump of curvature. */
  envelopes: Float64Array[];
}

/**
 * At `samples` + 1 points of each piece a tooth along the normal as long as
 * the curvature times `scale` (the size of the map), capped at 1.5 `scale`.
 * A jump of the comb at a village is a jump of curvature: C¹ but not C².
 */
export function curvatureComb(
  pieces: readonly Point[][],
  scale: number,
  samples: number,
): CurvatureComb {
  const teeth: number[] = [];
  const envelopes: Float64Array[] = [];
  let envelope: number[] = [];
  const close = () => {
    if (envelope.length >= 4) envelopes.push(Float64Array.from(envelope));
    envelope = [];
  };
  for (const piece of pieces) {
    for (let j = 0; j <= samples; j++) {
      let frame;
      try {
        frame = bezierFrenetFrame(piece, j / samples);
      } catch {
        // Zero speed (two villages on one spot): no direction, so no tooth here.
        close();
        continue;
      }
      const length = Math.max(-1.5, Math.min(1.5, -frame.curvature * scale)) * scale;
      const [x, y] = frame.point;
      const tip = [x + frame.normal[0] * length, y + frame.normal[1] * length];
      teeth.push(x, y, tip[0], tip[1], x, y);
      envelope.push(tip[0], tip[1]);
    }
    // Each piece has its own envelope: a step between pieces is the point.
    close();
  }
  return { teeth: Float64Array.from(teeth), envelopes };
}
