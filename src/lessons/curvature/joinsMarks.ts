import type { Painter } from '../../render/painter';
import { lineName } from '../../kit/plotMarks';
import type { Bounds } from '../../render/projection';
import { kappaContinuous, slopeContinuous } from './joinsScript';
import type { SplineJoin } from './joinsModel';
import { COLOURS, vectorArrow } from './marks';
import type { CurvatureModel } from './model';
import type { Series } from './plotFigure';

/** The Catmull-Rom spline's κ: dashed, in a colour of its own, and its name. */
export const CATMULL_COLOUR = 4;
export const CATMULL_KAPPA = 'κ of Catmull-Rom';
/** How far (in p̄) each side's tangent of κ is drawn either side of a join. */
const REACH = 0.3;

/** The joins part's plot: the natural spline's κ, then the Catmull-Rom spline's, dashed. */
export function joinSeries(m: CurvatureModel): Series[] {
  const out: Series[] = [];
  if (m.shown.has('kappa'))
    out.push({ name: 'κ', runs: m.plane!.kappa, colour: COLOURS.curvature });
  if (m.shown.has('catmull'))
    out.push({
      name: CATMULL_KAPPA,
      runs: m.joins!.catmull.kappa,
      colour: CATMULL_COLOUR,
      dash: [8, 5],
    });
  return out;
}

/** What a join of the natural spline is, in the lecture's words: "G², not G³". */
export function naturalJoinName(j: SplineJoin): string {
  if (!kappaContinuous(j)) return 'not G²';
  return slopeContinuous(j) ? 'G³' : 'G², not G³';
}

/** What a join of the Catmull-Rom spline is: "C¹, not G²". */
export function catmullJoinName(j: SplineJoin, continuity: string): string {
  const name = continuity.replace('1', '¹').replace('2', '²').replace('0', '⁰');
  return kappaContinuous(j) ? `Catmull-Rom ${name}, G²` : `Catmull-Rom ${name}, not G²`;
}

/**
 * A line at each join; once the slopes are shown, the tangent of κ from each
 * side carried across the join (two lines where κ has a kink); at the end,
 * each join named: the natural spline's at the foot, the Catmull-Rom's at the top.
 */
export function drawJoinMarks(
  painter: Painter,
  m: CurvatureModel,
  bounds: Bounds,
  thumbnail: boolean,
): void {
  const theme = painter.theme;
  const { natural, catmullJoins, catmull } = m.joins!;
  for (const j of natural)
    painter.segment([j.s, bounds.minY], [j.s, bounds.maxY], {
      color: theme.polygon,
      width: theme.sizes.thin,
      dash: [2, 4],
    });
  if (m.shown.has('slopes'))
    for (const j of natural) {
      if (!j.kappa || !j.slope) continue;
      for (const [kappa, slope] of [
        [j.kappa.before, j.slope.before.perParameter],
        [j.kappa.after, j.slope.after.perParameter],
      ])
        painter.segment(
          [j.s - REACH, kappa - REACH * slope],
          [j.s + REACH, kappa + REACH * slope],
          {
            color: theme.ink,
            width: theme.sizes.line,
            dash: [5, 3],
          },
        );
    }
  if (thumbnail || !m.shown.has('g3')) return;
  // Each join named against its own line, from the foot (the natural
  // spline's) or the top (Catmull-Rom's), where the name is clear, else not
  // at all: pushed along, two names stood together by one line (a phone).
  const style = { color: theme.ink, halo: true, bold: true };
  natural.forEach((j) =>
    lineName(painter, j.s, bounds, naturalJoinName(j), { ...style, from: 'foot' }),
  );
  catmullJoins.forEach((j, i) =>
    lineName(painter, j.s, bounds, catmullJoinName(j, catmull.pieces.joins[i].continuity), style),
  );
}

/**
 * At each join of the natural spline, ⅓P′ and ⅙P″ from the piece before
 * (one arrow each: the piece after gives the same, C²).
 */
export function drawJoinDerivatives(
  painter: Painter,
  joins: readonly SplineJoin[],
  labels: boolean,
): void {
  const theme = painter.theme;
  for (const j of joins) {
    vectorArrow(painter, j.point, j.first.before, 1 / 3, '⅓P′', theme.accent, labels);
    vectorArrow(
      painter,
      j.point,
      j.second.before,
      1 / 6,
      '⅙P″',
      painter.color(COLOURS.normal),
      labels,
    );
  }
}
