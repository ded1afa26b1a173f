import type { DrawInfo, Point } from '../../app/lesson';
import type { Painter, StrokeStyle } from '../../render/painter';
import type { SpaceScene } from '../../render/space';
import type { SurfaceModel } from './model';
import { coordinateIndex } from './state';
import { continuityName } from './notation';
import { drawPresetMarks, tangentPlane } from './presetMarks';
import { type Lift, drawPoints, scaled, weightDisc } from './spaceMarks';

// Each scene's own construction over the patch, revealed step by step.

/** De Casteljau's levels 1 … 3 of one curve (levels[0] is its control polygon). */
function drawLevels(
  scene: SpaceScene,
  painter: Painter,
  levels: readonly Point[][],
  color: string,
) {
  const theme = painter.theme;
  for (let r = 1; r < levels.length; r++) {
    scene.polyline(levels[r], { color, width: theme.sizes.thin, alpha: 0.8 });
    for (const p of levels[r])
      scene.dot(p, color, theme.sizes.point * (r === levels.length - 1 ? 1.2 : 0.6));
  }
}

export function drawConstruction(
  scene: SpaceScene,
  painter: Painter,
  m: SurfaceModel,
  info: DrawInfo,
  up: Lift,
): void {
  const theme = painter.theme;
  const { state, shown } = m;
  const color = (i: number) => painter.color(i);
  const polygon = (c: string): StrokeStyle => ({
    color: c,
    width: theme.sizes.line,
    dash: [2, 4],
  });
  const curve: StrokeStyle = { color: theme.curve, width: theme.sizes.curve, role: 'curve' };
  switch (state.mode) {
    case 'rows':
      if (shown.has('rowCurves'))
        m.rowCurves.forEach((c, i) => {
          scene.polyline(state.net[i], { color: color(i), width: theme.sizes.thin });
          scene.polyline(c, { color: color(i), width: theme.sizes.line });
        });
      if (shown.has('rowPoints')) drawPoints(scene, painter, m.rowPoints, 'r', info, color);
      if (shown.has('isoV')) {
        scene.polyline(m.rowPoints, polygon(theme.ink));
        scene.polyline(m.isoV.map(up), curve);
      }
      if (shown.has('isoU')) scene.polyline(m.isoU.map(up), curve);
      break;
    case 'casteljau': {
      // u first (columns, c₀ … c₃), then v first (rows, r₀ … r₃): the same three stages.
      const vFirst = shown.has('rows');
      const first = vFirst ? m.vThenU : m.uThenV;
      const name = vFirst ? 'r' : 'c';
      const lines = shown.is('columns') || shown.is('rows');
      const points = vFirst ? shown.has('rowPoints') : shown.has('columnPoints');
      if (shown.has('columns'))
        first.first.forEach((levels, i) => {
          scene.polyline(levels[0], { color: color(i), width: theme.sizes.thin });
          if (lines) drawLevels(scene, painter, levels, color(i));
        });
      if (points) {
        drawPoints(scene, painter, first.intermediate, name, info, color);
        scene.polyline(first.intermediate, polygon(theme.ink));
      }
      if (shown.is('uThenV') || shown.is('vThenU'))
        drawLevels(scene, painter, first.second, theme.ink);
      break;
    }
    case 'matrix': {
      const d = coordinateIndex(state.coordinate);
      if (shown.is('coordinates') && !info.thumbnail)
        for (const row of state.net)
          for (const p of row)
            // The step's matrix G holds them all: where one has no clear place, it is left out.
            scene.label(p[d].toFixed(2), p, {
              dx: 10,
              dy: -10,
              color: theme.ink,
              halo: true,
              optional: true,
            });
      if (shown.has('rowFactors')) {
        m.columnCurves.forEach((c, n) =>
          scene.polyline(c, { color: color(n), width: theme.sizes.line }),
        );
        m.columnPoints.forEach((p, n) => {
          scene.dot(p, color(n), theme.sizes.point * 1.3);
          if (!info.thumbnail)
            scene.label(`${state.coordinate}=${p[d].toFixed(3)}`, p, {
              dx: 10,
              dy: -10,
              color: color(n),
              halo: true,
              bold: true,
            });
        });
      }
      if (shown.has('columnFactors')) {
        scene.polyline(m.columnPoints, polygon(theme.ink));
        scene.polyline(m.isoU.map(up), curve);
      }
      break;
    }
    case 'weights': {
      const unit = theme.sizes.handle * 3.2;
      state.net.forEach((row, i) =>
        row.forEach((p, j) => {
          const w = shown.is('rowShares')
            ? m.rowShares[i] / 4
            : shown.is('columnShares')
              ? m.columnShares[j] / 4
              : m.weights[i][j];
          if (shown.has('rowShares'))
            weightDisc(scene, painter, p, Math.max(1, unit * Math.sqrt(w)));
          if (shown.has('average'))
            scene.line(p, m.point, {
              color: theme.accent,
              width: theme.sizes.line,
              alpha: Math.min(1, 0.15 + 3 * w),
            });
        }),
      );
      break;
    }
    case 'normal': {
      if (shown.has('uTangent')) scene.polyline(m.isoV.map(up), curve);
      if (shown.has('vTangent')) scene.polyline(m.isoU.map(up), { ...curve, color: color(1) });
      if (shown.has('tangentPlane')) tangentPlane(scene, painter, m);
      break;
    }
    case 'join':
      drawJoin(scene, painter, m, info, up);
      break;
    case 'patch':
      drawPresetMarks(scene, painter, m, info, up);
      break;
  }
}

/** The shared edge, then the legs across it coloured by how they continue, and the verdict. */
function drawJoin(scene: SpaceScene, painter: Painter, m: SurfaceModel, info: DrawInfo, up: Lift) {
  const theme = painter.theme;
  const { net, secondNet } = m.state;
  const color = (i: number) => painter.color(i);
  if (m.shown.has('edge'))
    scene.polyline(net[3].map(up), { color: theme.accent, width: theme.sizes.curve * 1.3 });
  if (!m.shown.has('legs') || !m.join) return;
  m.join.columns.forEach((c, n) => {
    const smooth = c !== 'none' && c !== 'C0';
    scene.polyline([net[2][n], net[3][n], secondNet[0][n], secondNet[1][n]], {
      color: smooth ? color(2) : color(1),
      width: theme.sizes.line * 1.4,
    });
  });
  // One verdict for the edge, at its middle: the weakest column decides.
  const weakest = m.join.weakest;
  const middle = net[3][1].map((value, i) => (value + net[3][2][i]) / 2);
  if (!info.thumbnail)
    scene.label(continuityName(weakest), middle, {
      dx: 12,
      dy: -16,
      color: weakest === 'none' || weakest === 'C0' ? color(1) : color(2),
      halo: true,
      bold: true,
    });
}

/** Marks above the handles: the tangent arrows and the normal, the first order's point to compare. */
export function drawOverConstruction(painter: Painter, m: SurfaceModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { state, shown } = m;
  const p = m.point;
  const label = (text: string, at: Point, color: string) => {
    if (!info.thumbnail) painter.label(text, at, { dx: 8, dy: -8, color, halo: true, bold: true });
  };
  // The normal of a net worth seeing, at its step (with the tangent plane, or alone).
  if (state.mode === 'patch' && (shown.has('normal') || shown.has('tangentPlane')) && m.normal) {
    const b = m.bounds;
    const size = Math.max(b.maxX - b.minX, b.maxY - b.minY) * 0.3;
    const end = p.map((x, i) => x + size * m.normal![i]);
    painter.arrow(p, end, { color: painter.color(2), width: theme.sizes.line * 1.3 });
    label('n', end, painter.color(2));
  }
  if (state.mode === 'normal') {
    const arrow = (v: readonly number[], text: string, color: string) => {
      const end = p.map((x, i) => x + v[i]);
      painter.arrow(p, end, { color, width: theme.sizes.line * 1.3 });
      label(text, end, color);
    };
    if (shown.has('uTangent')) arrow(scaled(m.du, 1 / 3), '∂P/∂u', painter.color(0));
    if (shown.has('vTangent')) arrow(scaled(m.dv, 1 / 3), '∂P/∂v', painter.color(1));
    if (shown.has('normal') && m.normal) {
      const b = m.bounds;
      const size = Math.max(b.maxX - b.minX, b.maxY - b.minY) * 0.3;
      arrow(scaled(m.normal, size), 'n', painter.color(2));
    }
  }
  if (state.mode === 'casteljau' && shown.has('rows')) {
    // The point of the first order, to compare with the second.
    painter.ring(m.uThenV.point, theme.sizes.point * 2.4, {
      color: theme.ink,
      width: theme.sizes.line,
    });
    // The step's formula says it with both points' coordinates: on a crowded
    // figure (a phone's) it is left out rather than boxed over the net.
    if (shown.is('vThenU') && !info.thumbnail)
      painter.label('u then v = v then u', m.uThenV.point, {
        dx: 8,
        dy: -8,
        color: theme.ink,
        halo: true,
        bold: true,
        optional: true,
      });
  }
}
