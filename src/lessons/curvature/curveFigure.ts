import { drawLegend } from '../../kit/legend';
import type { KitFigure } from '../../kit/lesson';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/projection';
import { words } from '../../kit/format';
import { COLOURS, arrowUnit, vectorArrow } from './marks';
import { drawJoinDerivatives } from './joinsMarks';
import type { CurvatureModel } from './model';
import type { PlaneModel } from './planeModel';
import { gradientHandles, gradientTips, planePoints, topViewPoints } from './points';
import { THROUGH_POINTS } from './sources';
import type { CurvatureState } from './state';

/** The plane cubic with its frame, circle and comb; or the top view of the space cubic; or the arc length ticks. */
export const curveFigure: KitFigure<CurvatureState, CurvatureModel> = {
  id: 'curve',
  title: 'The curve with P(t), its tangent, normal, osculating circle and curvature comb',
  kind: 'geometry',
  bounds(m) {
    if (m.state.part === 'space') {
      const polygon = m.state.spaceCurve === 'bezier' ? m.state.spacePoints : [];
      return boundsOf([...m.space.curve, ...polygon].map((p) => [p[0], p[1]]));
    }
    const plane = m.plane!;
    const circle = plane.at.circle;
    // The osculating circle is in view when it is not much larger than the curve.
    const round =
      m.state.part === 'plane' && circle && circle.radius < plane.size
        ? [0, 1].flatMap((d) =>
            [-1, 1].map((k) => circle.centre.map((v, e) => v + (e === d ? k * circle.radius : 0))),
          )
        : [];
    const box = boundsOf([
      ...m.state.points,
      ...curvePoints(plane),
      ...(m.joins ? curvePoints(m.joins.catmull) : []),
      ...gradientTips(m.state),
      ...plane.comb.flat().map((tooth) => tooth[1]),
      ...round,
    ]);
    // Room at the top for the note that says why N or T is undefined.
    return plane.at.why ? { ...box, maxY: box.maxY + 0.35 * (box.maxY - box.minY) } : box;
  },
  draw(painter, m, info) {
    const labels = !info.thumbnail;
    if (m.state.part === 'space') return drawTopView(painter, m, labels);
    // Say why instead of drawing nonsense: T is missing once T is shown (a cusp), N
    // once N is. First, so the labels drawn after it keep clear of it.
    const at = m.plane?.at;
    if (
      m.state.part === 'plane' &&
      at?.why &&
      labels &&
      m.shown.has(at.tangent ? 'normal' : 'tangent')
    )
      painter.note(at.why, { brief: at.brief ?? undefined });
    const plane = m.plane!;
    const theme = painter.theme;
    if (!THROUGH_POINTS[m.state.source])
      painter.polyline(m.state.points, {
        color: theme.polygon,
        width: theme.sizes.thin,
        dash: [6, 5],
      });
    for (const [i, tip] of gradientTips(m.state).entries())
      painter.segment(m.state.points[i], tip, { color: theme.polygon, width: theme.sizes.thin });
    if (m.state.part === 'plane' && m.shown.has('comb')) drawComb(painter, plane);
    // The joins part: the Catmull-Rom spline of the same points, dashed, beside the natural one.
    if (m.joins && m.shown.has('catmull'))
      painter.polylineFlat(m.joins.catmull.curve, {
        color: theme.muted,
        width: theme.sizes.curve * 0.8,
        dash: [10, 6],
      });
    if (m.joins && m.shown.has('c2')) drawJoinDerivatives(painter, m.joins.natural, labels);
    painter.polylineFlat(plane.curve, {
      color: theme.curve,
      width: theme.sizes.curve,
      role: 'curve',
    });
    for (const join of plane.pieces.joins)
      painter.dot(join.point, theme.ink, theme.sizes.point * 0.6);
    if (m.state.part === 'arc') drawTicks(painter, m, labels);
    else drawFrame(painter, m, plane, labels);
  },
  points: [planePoints, gradientHandles, topViewPoints],
  trail: (m) => (m.state.part === 'space' ? m.space.at.point.slice(0, 2) : m.plane!.at.point),
  weight: 3,
};

/** Every eighth sample of the curve: a spline through the points may swing beyond them. */
function curvePoints(plane: Pick<PlaneModel, 'curve'>): Point[] {
  const out: Point[] = [];
  for (let i = 0; i < plane.curve.length; i += 16) out.push([plane.curve[i], plane.curve[i + 1]]);
  return out;
}

function drawFrame(painter: Painter, m: CurvatureModel, plane: PlaneModel, labels: boolean): void {
  const theme = painter.theme;
  const { shown } = m;
  const at = plane.at;
  const unit = arrowUnit(plane.size);
  if (shown.has('inflections')) {
    for (const mark of plane.marks)
      markPoint(painter, mark.point, markWords(mark.kind, mark.t, plane), labels);
  }
  if (shown.has('curvature') && at.circle) {
    const colour = painter.color(COLOURS.curvature);
    painter.circle(at.circle.centre, at.circle.radius, { color: colour, width: theme.sizes.line });
    painter.segment(at.point, at.circle.centre, {
      color: colour,
      width: theme.sizes.thin,
      dash: [5, 4],
    });
    painter.dot(at.circle.centre, colour, theme.sizes.point * 0.8);
    if (labels)
      painter.label(`R = 1/|κ| = ${words(at.circle.radius)}`, at.circle.centre, {
        color: colour,
        halo: true,
        dx: 8,
        dy: 18,
      });
  }
  if (shown.has('velocity') && at.speed > 0) {
    // On several pieces P′ is dP/dp̄, the piece's own derivative (see planeScript).
    const name = plane.pieces.segments.length > 1 ? '⅓P′(p̄)' : '⅓P′(t)';
    vectorArrow(painter, at.point, at.velocity, 1 / 3, name, theme.accent, labels);
  }
  if (shown.has('tangent') && at.tangent)
    vectorArrow(painter, at.point, at.tangent, unit, 'T', painter.color(COLOURS.tangent), labels);
  if (shown.has('normal') && at.normal)
    vectorArrow(painter, at.point, at.normal, unit, 'N', painter.color(COLOURS.normal), labels);
  painter.movingPoint(at.point, 1.3);
  if (labels) painter.label('P(t)', at.point, { halo: true, dx: -14, dy: 22, align: 'right' });
}

function drawComb(painter: Painter, plane: PlaneModel): void {
  const colour = painter.color(COLOURS.curvature);
  const width = painter.theme.sizes.thin;
  for (const run of plane.comb) {
    for (const [base, tip] of run) painter.segment(base, tip, { color: colour, width, alpha: 0.7 });
    painter.polyline(
      run.map((tooth) => tooth[1]),
      { color: colour, width: painter.theme.sizes.line },
    );
  }
}

function markPoint(painter: Painter, at: Point, text: string, labels: boolean): void {
  // Dashed and unfilled: a solid ring of this size reads as one more control
  // point's handle (the natural spline's five points looked like six).
  const width = painter.theme.sizes.line;
  painter.ring(at, painter.theme.sizes.point * 2, {
    color: painter.theme.ink,
    width,
    dash: [width * 2.5, width * 2],
  });
  // The κ plot marks the same t with "κ = 0" and the caption says what it is:
  // where the figure is crowded (a phone's) the ring stands without its words.
  if (labels) painter.label(text, at, { halo: true, dx: 12, dy: -12, bold: true, optional: true });
}

function drawTicks(painter: Painter, m: CurvatureModel, labels: boolean): void {
  const theme = painter.theme;
  const arc = m.arc!;
  const { shown } = m;
  const length = 0.05 * m.plane!.size;
  const tick = (
    points: readonly Point[],
    directions: readonly Point[],
    colour: string,
    side: number,
    alpha: number,
  ) =>
    points.forEach((q, i) => {
      const v = directions[i];
      const across = [-side * v[1], side * v[0]];
      painter.segment(q, [q[0] + length * across[0], q[1] + length * across[1]], {
        color: colour,
        width: theme.sizes.line * 1.3,
        alpha,
      });
      painter.dot(q, colour, theme.sizes.point * 0.7);
    });
  // While equal steps of s are new, the ticks of equal t fade behind them.
  const faded = shown.is('equalLength') ? 0.3 : 1;
  if (shown.has('ticks')) tick(arc.byT, arc.byTDirection, painter.color(0), 1, faded);
  if (shown.has('equalLength')) tick(arc.byS, arc.bySDirection, painter.color(1), -1, 1);
  painter.movingPoint(m.plane!.at.point, 1.3);
  if (!labels) return;
  painter.label('P(t)', m.plane!.at.point, { halo: true, dx: -14, dy: 22, align: 'right' });
  // The key in the corner where it hides least: a name at a fixed spot sat on a handle.
  drawLegend(painter, [
    ...(shown.has('ticks')
      ? [{ text: `■ ${m.state.equalSteps} equal steps of t`, color: painter.color(0) }]
      : []),
    ...(shown.has('equalLength')
      ? [{ text: `■ ${m.state.equalSteps} equal steps of arc length s`, color: painter.color(1) }]
      : []),
  ]);
}

function drawTopView(painter: Painter, m: CurvatureModel, labels: boolean): void {
  const theme = painter.theme;
  const flat = (points: readonly Point[]) => points.map((p) => [p[0], p[1]]);
  if (m.state.spaceCurve === 'bezier')
    painter.polyline(flat(m.state.spacePoints), {
      color: theme.polygon,
      width: theme.sizes.thin,
      dash: [6, 5],
    });
  painter.polyline(flat(m.space.curve), {
    color: theme.curve,
    width: theme.sizes.curve,
    role: 'curve',
  });
  painter.movingPoint(m.space.at.point.slice(0, 2), 1.3);
  if (labels) drawLegend(painter, [{ text: 'Top view (x, y)', color: theme.muted }]);
}

/**
 * A mark's label. Speed 0 inside the curve is a cusp; at an end (a Catmull-Rom
 * spline's zero end gradients) the curve just starts or stops. κ = 0 inside is
 * an inflection; at an end (a natural spline's P″ = 0) the curve only ends
 * straight, with no bend on the other side to turn to.
 */
export function markWords(kind: 'inflection' | 'cusp', s: number, plane: PlaneModel): string {
  // The model puts a mark at an end exactly on 0 or on the number of pieces.
  const end = s === 0 || s === plane.pieces.segments.length;
  if (kind === 'cusp') return end ? 'P′ = 0 at the end' : 'cusp: P′ = 0';
  return end ? 'κ = 0 at the end' : 'inflection: κ = 0';
}
