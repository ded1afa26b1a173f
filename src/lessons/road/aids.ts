import type { DrawInfo } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import { LABEL_VILLAGES } from './points';
import { drawRoadway } from './mapDrawing';
import type { RoadModel } from './model';
import { isFixed } from './solve';
import { compared } from './view';

// What the map draws around the road to show how it was built: the chosen
// gradients and control points of each method, the roads it must join, and
// the solve as it goes. Every position comes from the model.

/** Up to this many villages the quadratic's control polygon is drawn. */
const POLYGON_VILLAGES = 60;

/** Construction lines of each method: gradients, control points, chosen ends. */
export function drawMethodAids(painter: Painter, m: RoadModel, info: DrawInfo): void {
  if (info.thumbnail) return;
  const { theme } = painter;
  const { state } = m;
  const v = state.villages;
  const arrow = { color: theme.accent, width: theme.sizes.line };
  if (m.usesQuadraticHandle) {
    const controls = m.quadraticPolygon;
    if (controls && v.length <= POLYGON_VILLAGES) {
      // The control polygon P0 B0 P1 B1 …: each Bi is the reflection of B(i−1) in Pi.
      painter.polyline(controls.polygon, {
        color: theme.polygon,
        width: theme.sizes.thin,
        dash: [5, 5],
      });
      for (const b of controls.controls) painter.dot(b, theme.polygon, theme.sizes.point * 0.7);
    }
    painter.arrow(v[0], m.quadraticControl, arrow);
  }
  if (m.usesEndGradients) {
    painter.arrow(v[0], m.endHandles[0], arrow);
    painter.arrow(v[v.length - 1], m.endHandles[1], arrow);
  }
  if (
    !compared(state) &&
    state.road === 'hermite' &&
    v.length <= LABEL_VILLAGES &&
    m.gradientTips
  ) {
    // The gradient of each piece at each village, from the parabola through it and its neighbours.
    m.gradientTips.forEach((tip, i) => {
      if (state.ends && (i === 0 || i === v.length - 1)) return;
      painter.arrow(v[i], tip, { color: painter.color(0), width: theme.sizes.line });
    });
  }
}

/** The roads the new one must join at P0 and Pm, leaving along the chosen gradients. */
export function drawOtherRoads(painter: Painter, m: RoadModel): void {
  const [start, end] = m.otherRoads;
  const faint = painter.theme.curveFaint;
  for (const roadway of m.otherRoadways) drawRoadway(painter, [roadway], faint);
  const style = {
    size: painter.theme.sizes.small,
    color: painter.theme.muted,
    halo: true,
    align: 'center' as const,
    dy: -painter.theme.sizes.curve * 3,
  };
  painter.label('existing road', start, style);
  painter.label('existing road', end, style);
}

/** While the solve is under way: the road not yet built, and the rows swept so far. */
export function drawSolveProgress(painter: Painter, m: RoadModel): void {
  const { theme } = painter;
  const { state, progress, solve } = m;
  painter.polyline(state.villages, {
    color: theme.curveFaint,
    width: theme.sizes.line,
    dash: [6, 6],
  });
  if (!progress || !solve || state.villages.length > LABEL_VILLAGES) return;
  // Row i of the system belongs to village Pi: mark the rows swept so far.
  state.villages.forEach((p, i) => {
    if (i >= progress.swept) return;
    // The row being swept is the current one until the back substitution starts.
    const current = i === progress.row && !m.shown.has('substitution');
    painter.ring(p, theme.sizes.handle * (current ? 2.4 : 1.7), {
      color: current ? theme.accent : painter.color(0),
      width: current ? theme.sizes.line * 1.5 : theme.sizes.thin,
    });
  });
}

/**
 * Each gradient fixed so far, as an arrow D/3: over the villages' labels, so
 * the new one is seen; the one this step fixes is named, as the caption names it.
 */
export function drawFixedGradients(painter: Painter, m: RoadModel): void {
  const { theme } = painter;
  const { state, progress, solve, gradientTips } = m;
  if (!m.solving || !progress || !solve || !gradientTips || state.villages.length > LABEL_VILLAGES)
    return;
  state.villages.forEach((p, i) => {
    if (!isFixed(solve.n, progress, i)) return;
    const current = i === progress.row;
    const color = current ? theme.accent : painter.color(0);
    painter.arrow(p, gradientTips[i], { color, width: theme.sizes.line * (current ? 1.4 : 1) });
    if (current)
      painter.label(`⅓D_${i}`, gradientTips[i], {
        color,
        halo: true,
        bold: true,
        dx: 6,
        dy: -6,
      });
  });
}

/** "p̄ = 2.40: segment 2, p = 0.40" beside the marker. */
export function drawMarkerLabel(painter: Painter, m: RoadModel): void {
  const marker = m.visible?.marker;
  if (!marker) return;
  const { sizes } = painter.theme;
  // On the side away from the villages, so it covers none of them or their names (a phone's narrow map).
  const v = m.state.villages;
  // A narrow map (a phone) gets the short form: the panel has the rest.
  const narrow = painter.view.width < 40 * sizes.small;
  painter.labelClear(
    narrow
      ? `p̄ = ${m.state.pBar.toFixed(2)}`
      : `p̄ = ${m.state.pBar.toFixed(2)}: segment ${marker.piece}, p = ${marker.p.toFixed(2)}`,
    marker.point,
    v.length <= LABEL_VILLAGES ? v : [v[marker.piece], v[Math.min(marker.piece + 1, v.length - 1)]],
    { size: sizes.small, box: true },
  );
}
