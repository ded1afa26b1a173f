import type { DrawInfo } from '../../app/lesson';
import type { Painter, StrokeStyle } from '../../render/painter';
import type { SpaceScene } from '../../render/space';
import { type Lift, drawPoints, scaled, weightDisc } from './spaceMarks';
import type { SurfaceModel } from './model';

// What the steps of the nets worth seeing (flat, saddle, bump, wave, not
// planar) draw over the patch, by name.

/** Weight dots on the control points (area as the weight), and lines to the point they pull. */
function weightDots(scene: SpaceScene, painter: Painter, m: SurfaceModel, toPoint: boolean) {
  const theme = painter.theme;
  const unit = theme.sizes.handle * 3.2;
  m.state.net.forEach((row, i) =>
    row.forEach((p, j) => {
      const w = m.weights[i][j];
      weightDisc(scene, painter, p, Math.max(1, unit * Math.sqrt(w)));
      if (toPoint)
        scene.line(p, m.point, {
          color: theme.accent,
          width: theme.sizes.line,
          alpha: Math.min(1, 0.15 + 3 * w),
        });
    }),
  );
}

/** The tangent plane at P(u, v): the parallelogram of ∂P/∂u and ∂P/∂v (a third of each), either side. */
export function tangentPlane(scene: SpaceScene, painter: Painter, m: SurfaceModel) {
  const a = scaled(m.du, 1 / 3);
  const b = scaled(m.dv, 1 / 3);
  const p = m.point;
  const corner = (s: number, t: number) => p.map((x, i) => x + s * a[i] + t * b[i]);
  scene.quad([corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)], painter.color(4), {
    alpha: 0.45,
  });
}

/**
 * What the steps of the nets worth seeing add, by name: the plane of a flat
 * net, the twisted quadrilateral of the corners, one iso-curve with its control
 * points, the row and column curves, the weights, the tangent plane (its
 * normal is drawn over the handles).
 */
export function drawPresetMarks(
  scene: SpaceScene,
  painter: Painter,
  m: SurfaceModel,
  info: DrawInfo,
  up: Lift,
) {
  const theme = painter.theme;
  const { state, shown } = m;
  const net = state.net;
  const color = (i: number) => painter.color(i);
  const corners = [net[0][0], net[3][0], net[3][3], net[0][3]];
  const curve: StrokeStyle = { color: theme.curve, width: theme.sizes.curve, role: 'curve' };
  const polygon: StrokeStyle = { color: theme.ink, width: theme.sizes.line, dash: [2, 4] };
  if (shown.has('plane') && !shown.has('surface'))
    scene.quad(corners, painter.color(5), { alpha: 0.3 });
  // The twisted quadrilateral of the corners, until the patch that meets them is drawn.
  if (shown.has('cornerQuad') && !shown.has('surface'))
    scene.polyline([...corners, corners[0]], {
      color: theme.accent,
      width: theme.sizes.line * 1.4,
    });
  // One iso-curve with its four control points, at its own step (named while the patch is not drawn).
  const named = !shown.has('surface');
  if (shown.is('isoU')) {
    scene.polyline(m.columnPoints, polygon);
    drawPoints(scene, painter, m.columnPoints, 'c', info, color, named);
    scene.polyline(m.isoU.map(up), curve);
  }
  if (shown.is('isoV')) {
    scene.polyline(m.rowPoints, polygon);
    drawPoints(scene, painter, m.rowPoints, 'r', info, color, named);
    scene.polyline(m.isoV.map(up), { ...curve, color: color(1) });
  }
  // The row and column curves, until the patch they make is drawn.
  if (!shown.has('surface')) {
    if (shown.has('columnCurves'))
      m.columnCurves.forEach((c, n) =>
        scene.polyline(c, { color: color(n), width: theme.sizes.line }),
      );
    if (shown.has('rowCurves'))
      m.rowCurves.forEach((c, i) =>
        scene.polyline(c, { color: color(i + 4), width: theme.sizes.line, dash: [6, 3] }),
      );
  }
  if (shown.has('shares')) weightDots(scene, painter, m, true);
  if (shown.has('tangentPlane')) tangentPlane(scene, painter, m);
}
