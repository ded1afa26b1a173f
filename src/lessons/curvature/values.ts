import type { Point } from '../../math';
import { COLOURS } from './marks';
import type { CurvatureModel } from './model';
import type { CurvatureState } from './state';

/** Twelve significant digits: enough to check κ against its closed form to 1e-9. */
export const precise = (value: number) => Number(value.toPrecision(12)).toString();
const vector = (v: Point | null) =>
  v ? `(${v.map((x) => Number(x.toFixed(4))).join(', ')})` : 'undefined';

interface Row {
  cells: (string | { text: string; swatch?: string })[];
  data?: Record<string, string>;
}

/** The rows of the panel's table: the values at t, or the arc length table. */
export function valueRows(
  m: CurvatureModel,
  state: CurvatureState,
  palette: readonly string[],
): Row[] {
  const swatch = (k: number) => palette[k % palette.length];
  const named = (name: string, value: string, colour?: number): Row => ({
    cells: [{ text: name, swatch: colour === undefined ? undefined : swatch(colour) }, value],
    data: { quantity: name },
  });
  if (state.part === 'plane') {
    const at = m.plane!.at;
    const global =
      m.plane!.pieces.segments.length > 1
        ? [
            named('s = pieces·t', precise(at.s)),
            named('piece i, local u', `${at.piece}, ${precise(at.u)}`),
          ]
        : [];
    return [
      named('t', precise(at.t)),
      ...global,
      named('P(t)', vector(at.point)),
      named('P′(t)', vector(at.velocity)),
      named('|P′(t)|', precise(at.speed)),
      named('T', vector(at.tangent), COLOURS.tangent),
      named('N', vector(at.normal), COLOURS.normal),
      named('κ', at.curvature === null ? 'undefined' : precise(at.curvature), COLOURS.curvature),
      named(
        'R = 1/|κ|',
        at.circle ? precise(at.circle.radius) : 'undefined (infinite or no circle)',
      ),
    ];
  }
  if (state.part === 'space') {
    const at = m.space.at;
    const out = [
      named('t', precise(at.t)),
      named('P(t)', vector(at.point)),
      named('T', vector(at.tangent), COLOURS.tangent),
      named('N', vector(at.normal), COLOURS.normal),
      named('B', vector(at.binormal), COLOURS.binormal),
      named('κ', at.curvature === null ? 'undefined' : precise(at.curvature), COLOURS.curvature),
      named('τ', at.torsion === null ? 'undefined' : precise(at.torsion), COLOURS.torsion),
    ];
    if (m.space.closed)
      out.push(
        named('a/(a² + b²)', precise(m.space.closed.curvature)),
        named('b/(a² + b²)', precise(m.space.closed.torsion)),
      );
    return out;
  }
  return [];
}

/** The arc length table: s at t = i/n, and t at s = iL/n. */
export function arcRows(m: CurvatureModel): Row[] {
  const arc = m.arc!;
  return arc.table.map((row, i) => ({
    cells: [
      String(i),
      precise(row.t),
      precise(row.s),
      precise(arc.equal[i].s),
      precise(arc.equal[i].t),
    ],
    data: { quantity: `row ${i}` },
  }));
}
