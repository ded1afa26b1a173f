import type { DrawInfo } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import { drawCursor, drawMarks, drawPolygon, drawSegments, hint, ringHovered } from './drawParts';
import { haloRadius } from './halo';
import { haloIds } from './ids';
import type { CircleModel, KnotModel, NurbsModel, ProjectiveModel } from './model';
import { superscript } from './notation';
import { CIRCLE } from './nurbsGeometry';

/** The general B-spline on its knots: the curve, its joins and their continuity. */
export function drawKnots(painter: Painter, m: KnotModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('knots')) drawPolygon(painter, m.state.points);
  // At the last row, N(i,p): ring the points that act at u.
  if (shown.is('row') && shown.count('row') === m.degree + 1) {
    m.basis.forEach((b, i) => {
      if (b > 0)
        painter.ring(m.state.points[i], theme.sizes.handle * 2.2, {
          color: painter.color(i),
          width: theme.sizes.line * 1.5,
        });
    });
  }
  if (shown.has('curve')) {
    drawSegments(painter, m, info);
    for (const join of m.joins) {
      const text = join.continuity < 0 ? 'jump' : `C${superscript(join.continuity)}`;
      painter.dot(join.at, theme.ink, theme.sizes.point);
      if (!info.thumbnail)
        painter.label(text, join.at, {
          dx: 10,
          dy: 22,
          color: theme.ink,
          halo: true,
          box: join.continuity <= 0,
        });
    }
    drawCursor(painter, m, 'P(u)', info);
  }
  ringHovered(painter, m, info);
}

/** NURBS weights: the plain B-spline, then the weights as halos and the rational curve. */
export function drawNurbs(painter: Painter, m: NurbsModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('plain')) drawPolygon(painter, m.state.points, false);
  if (shown.is('plain'))
    painter.polylineFlat(m.rational.plain, {
      color: theme.curve,
      width: theme.sizes.curve,
      role: 'curve',
    });
  if (shown.has('weights')) {
    painter.polylineFlat(m.rational.plain, {
      color: theme.muted,
      width: theme.sizes.line,
      dash: [5, 5],
    });
    drawSegments(painter, m, info);
    weightHalos(painter, m, info);
  }
  if (shown.has('sum')) drawCursor(painter, m, 'P(u)', info);
}

/** The exact circle: weights as halos, four arcs, samples on the circle, and with weights 1. */
export function drawCircle(painter: Painter, m: CircleModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('weights')) {
    drawPolygon(painter, m.state.points, false);
    weightHalos(painter, m, info);
  }
  if (shown.has('arcs')) drawSegments(painter, m, info);
  if (shown.has('samples')) {
    painter.circle(CIRCLE.centre, CIRCLE.radius, {
      color: theme.ink,
      width: theme.sizes.thin,
      dash: [2, 4],
    });
    m.circle.samples.forEach((point) => painter.dot(point, theme.ink, theme.sizes.point * 0.8));
  }
  if (shown.has('plain')) {
    const plain = m.rational.plain;
    painter.polylineFlat(plain, {
      color: theme.muted,
      width: theme.sizes.line * 1.3,
      dash: [6, 4],
    });
    // Named where it strays farthest from the circle: unnamed, beside "with
    // every weight 1 instead", it was one more dark ring round the circle.
    if (!info.thumbnail) {
      const [cx, cy] = CIRCLE.centre;
      let far = 0;
      let farthest = -1;
      for (let k = 0; k < plain.length; k += 2) {
        const off = Math.abs(Math.hypot(plain[k] - cx, plain[k + 1] - cy) - CIRCLE.radius);
        if (off > farthest) [far, farthest] = [k, off];
      }
      painter.label('all w_{i} = 1', [plain[far], plain[far + 1]], {
        color: theme.muted,
        halo: true,
      });
    }
  }
}

/** The perspective map: the mapped points with their new weights, then with the old ones. */
export function drawProjective(painter: Painter, m: ProjectiveModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown, projective: pr } = m;
  if (shown.has('curve')) {
    drawPolygon(painter, m.state.points, false);
    drawSegments(painter, m, info);
  }
  if (pr.error) {
    if (shown.has('map')) hint(painter, info, pr.error);
    return;
  }
  if (shown.has('map')) {
    drawPolygon(painter, pr.points);
    painter.polylineFlat(pr.curve, { color: theme.curve, width: theme.sizes.curve, role: 'curve' });
    pr.mapped
      .filter((_, k) => k % 2 === 0)
      .forEach((point) =>
        painter.ring(point, theme.sizes.point * 1.2, {
          color: theme.accent,
          width: theme.sizes.thin,
        }),
      );
    drawMarks(
      painter,
      pr.points,
      theme.polygon,
      info.thumbnail ? null : pr.weights.map((w, i) => `w′_{${i}} = ${w.toFixed(2)}`),
      info,
    );
  }
  if (shown.has('oldWeights')) {
    painter.polylineFlat(pr.plain, {
      color: painter.color(3),
      width: theme.sizes.line * 1.8,
      dash: [8, 5],
    });
    if (!info.thumbnail) {
      const at = (pr.plain.length >> 2) & ~1;
      painter.label('old weights', [pr.plain[at], pr.plain[at + 1]], {
        dx: 12,
        dy: -12,
        color: painter.color(3),
        halo: true,
      });
    }
  }
}

/**
 * A halo around each control point, its radius growing with the weight (drag
 * the ring to change it), and the weight written. The hovered or dragged ring is drawn bold.
 */
function weightHalos(painter: Painter, m: NurbsModel | CircleModel, info: DrawInfo): void {
  const theme = painter.theme;
  const pixels = 1 / painter.view.worldLength(1);
  // Each weight is its point's: written round that point, nearer it than any other.
  const rivals = m.state.points.map((p) => painter.view.toScreen(p) as [number, number]);
  m.weights.forEach((w, i) => {
    const point = m.state.points[i];
    const strong = haloIds.index(info.hover) === i;
    const radius = haloRadius(w, m.rational.haloUnit) * pixels;
    painter.ring(
      point,
      radius,
      { color: theme.accent, width: strong ? theme.sizes.line * 1.5 : theme.sizes.thin },
      theme.accent,
      strong ? 0.2 : 0.12,
    );
    if (!info.thumbnail) {
      painter.label(`w_{${i}} = ${Number(w.toFixed(3))}`, point, {
        around: Math.min(radius, theme.sizes.handle * 2),
        rivals,
        color: theme.ink,
        halo: true,
        size: theme.sizes.label * 0.85,
      });
    }
  });
}
