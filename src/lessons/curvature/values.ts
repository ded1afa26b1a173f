import { trimmed } from '../../kit/format';
import type { Point } from '../../math';
import { COLOURS } from './marks';
import type { CurvatureModel } from './model';
import type { CurvatureState } from './state';

/**
 * A number in the tables: four decimals at most (the kit's `trimmed`, so a
 * rounding residue reads 0). The row keeps the whole number in `data-value`
 * for whoever checks it against the maths.
 */
const shown = (value: number) => trimmed(value, 4);
/** A vector whole on its line (no-break spaces): the value column may wrap between words, not inside it. */
const vector = (v: Point | null) => (v ? `(${v.map(shown).join(',\u00A0')})` : 'undefined');

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
  const named = (name: string, text: string, colour?: number): Row => ({
    cells: [{ text: name, swatch: colour === undefined ? undefined : swatch(colour) }, text],
    // Rows are kept by place: every row writes data-value, so none keeps another's number.
    data: { quantity: name, value: '' },
  });
  /** A row of one number: shown to four decimals, whole in data-value ('' where undefined: the table keeps no stale number). */
  const number = (name: string, value: number | null, colour?: number, otherwise = 'undefined') => {
    const row = named(name, value === null ? otherwise : shown(value), colour);
    return { ...row, data: { quantity: name, value: value === null ? '' : String(value) } };
  };
  if (state.part === 'joins') {
    // Both sides of each join: the natural spline's κ and dκ/ds, the Catmull-Rom spline's κ.
    const pair = (name: string, sides: [number, number] | null) =>
      named(name, sides ? `${shown(sides[0])} | ${shown(sides[1])}` : 'undefined');
    const { natural, catmullJoins } = m.joins!;
    return natural.flatMap((j, i) => {
      const other = catmullJoins[i];
      return [
        pair(`κ before | after p̄ = ${j.s}`, j.kappa && [j.kappa.before, j.kappa.after]),
        pair(
          `dκ/ds before | after p̄ = ${j.s}`,
          j.slope && [j.slope.before.perLength, j.slope.after.perLength],
        ),
        pair(
          `Catmull-Rom κ before | after p̄ = ${j.s}`,
          other?.kappa ? [other.kappa.before, other.kappa.after] : null,
        ),
      ];
    });
  }
  if (state.part === 'plane') {
    const at = m.plane!.at;
    // On several pieces P′ is the piece's own dP/dp̄ (see planeScript).
    const pieced = m.plane!.pieces.segments.length > 1;
    const x = pieced ? 'p̄' : 't';
    const global = pieced
      ? [number('p̄ = pieces·t', at.s), named('piece i, local p', `${at.piece}, ${shown(at.u)}`)]
      : [];
    return [
      number('t', at.t),
      ...global,
      named(`P(${x})`, vector(at.point)),
      named(`P′(${x})`, vector(at.velocity)),
      number(`|P′(${x})|`, at.speed),
      named('T', vector(at.tangent), COLOURS.tangent),
      named('N', vector(at.normal), COLOURS.normal),
      number('κ', at.curvature, COLOURS.curvature),
      number(
        'R = 1/|κ|',
        at.circle?.radius ?? null,
        undefined,
        'undefined (infinite or no circle)',
      ),
    ];
  }
  if (state.part === 'space') {
    const at = m.space.at;
    const out = [
      number('t', at.t),
      named('P(t)', vector(at.point)),
      named('T', vector(at.tangent), COLOURS.tangent),
      named('N', vector(at.normal), COLOURS.normal),
      named('B', vector(at.binormal), COLOURS.binormal),
      number('κ', at.curvature, COLOURS.curvature),
      number('τ', at.torsion, COLOURS.torsion),
    ];
    if (m.space.closed)
      out.push(
        number('a/(a² + b²)', m.space.closed.curvature),
        number('b/(a² + b²)', m.space.closed.torsion),
      );
    return out;
  }
  return [];
}

/** The arc length table: s at t = i/n, and t at s = iL/n (whole numbers in data-t, data-s, data-equal-s, data-equal-t). */
export function arcRows(m: CurvatureModel): Row[] {
  const arc = m.arc!;
  return arc.table.map((row, i) => ({
    cells: [String(i), shown(row.t), shown(row.s), shown(arc.equal[i].s), shown(arc.equal[i].t)],
    data: {
      quantity: `row ${i}`,
      t: String(row.t),
      s: String(row.s),
      equalS: String(arc.equal[i].s),
      equalT: String(arc.equal[i].t),
    },
  }));
}
