import type { DrawInfo, Point } from '../../app/lesson';
import type { Painter, StrokeStyle } from '../../render/painter';
import type { SpaceScene } from '../../render/space';
import type { SurfaceModel } from './model';
import { coordinateIndex } from './state';
import { continuityName } from './steps';

type Lift = (p: readonly number[]) => Point;

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

function drawPoints(
  scene: SpaceScene,
  painter: Painter,
  points: readonly Point[],
  name: string,
  info: DrawInfo,
  color: (i: number) => string,
) {
  const theme = painter.theme;
  points.forEach((p, i) => {
    scene.dot(p, color(i), theme.sizes.point * 1.3);
    if (!info.thumbnail)
      scene.label(`${name}_{${i}}`, p, {
        dx: 10,
        dy: -10,
        color: color(i),
        halo: true,
        bold: true,
      });
  });
}

export function drawConstruction(
  scene: SpaceScene,
  painter: Painter,
  m: SurfaceModel,
  info: DrawInfo,
  up: Lift,
): void {
  const theme = painter.theme;
  const { state } = m;
  const k = state.k;
  const color = (i: number) => painter.color(i);
  const polygon = (c: string): StrokeStyle => ({
    color: c,
    width: theme.sizes.line,
    dash: [2, 4],
  });
  const curve: StrokeStyle = { color: theme.curve, width: theme.sizes.curve, role: 'curve' };
  switch (state.s) {
    case 'rows':
      if (k >= 1)
        m.rowCurves.forEach((c, i) => {
          scene.polyline(state.x[i], { color: color(i), width: theme.sizes.thin });
          scene.polyline(c, { color: color(i), width: theme.sizes.line });
        });
      if (k >= 2) drawPoints(scene, painter, m.rowPoints, 'r', info, color);
      if (k >= 3) {
        scene.polyline(m.rowPoints, polygon(theme.ink));
        scene.polyline(m.isoV.map(up), curve);
      }
      if (k >= 5) scene.polyline(m.isoU.map(up), curve);
      break;
    case 'casteljau': {
      const first = k <= 3 ? m.uThenV : m.vThenU;
      const local = k <= 3 ? k : k - 3;
      const name = k <= 3 ? 'c' : 'r';
      if (local >= 1)
        first.first.forEach((levels, i) => {
          scene.polyline(levels[0], { color: color(i), width: theme.sizes.thin });
          if (local === 1) drawLevels(scene, painter, levels, color(i));
        });
      if (local >= 2) {
        drawPoints(scene, painter, first.intermediate, name, info, color);
        scene.polyline(first.intermediate, polygon(theme.ink));
      }
      if (local >= 3) drawLevels(scene, painter, first.second, theme.ink);
      break;
    }
    case 'matrix': {
      const d = coordinateIndex(state.c);
      if (k === 0 && !info.thumbnail)
        for (const row of state.x)
          for (const p of row)
            scene.label(p[d].toFixed(2), p, { dx: 10, dy: -10, color: theme.ink, halo: true });
      if (k >= 1) {
        m.columnCurves.forEach((c, n) =>
          scene.polyline(c, { color: color(n), width: theme.sizes.line }),
        );
        m.columnPoints.forEach((p, n) => {
          scene.dot(p, color(n), theme.sizes.point * 1.3);
          if (!info.thumbnail)
            scene.label(`${state.c}=${p[d].toFixed(3)}`, p, {
              dx: 10,
              dy: -10,
              color: color(n),
              halo: true,
              bold: true,
            });
        });
      }
      if (k >= 2) {
        scene.polyline(m.columnPoints, polygon(theme.ink));
        scene.polyline(m.isoU.map(up), curve);
      }
      break;
    }
    case 'weights': {
      const fu = m.weights.map((row) => row.reduce((s, w) => s + w, 0));
      const fv = m.weights[0].map((_, n) => m.weights.reduce((s, row) => s + row[n], 0));
      const unit = theme.sizes.handle * 3.2;
      state.x.forEach((row, i) =>
        row.forEach((p, j) => {
          const w = k === 1 ? fu[i] / 4 : k === 2 ? fv[j] / 4 : m.weights[i][j];
          if (k >= 1) scene.dot(p, theme.accent, Math.max(1, unit * Math.sqrt(w)));
          if (k >= 4)
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
      if (k >= 1) scene.polyline(m.isoV.map(up), curve);
      if (k >= 2) scene.polyline(m.isoU.map(up), { ...curve, color: color(1) });
      if (k >= 4) {
        const a = scaled(m.du, 1 / 3);
        const b = scaled(m.dv, 1 / 3);
        const p = m.point;
        const corner = (s: number, t: number) => p.map((x, i) => x + s * a[i] + t * b[i]);
        scene.quad([corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)], painter.color(4), {
          alpha: 0.45,
        });
      }
      break;
    }
    case 'join': {
      if (k >= 1)
        scene.polyline(state.x[3].map(up), { color: theme.accent, width: theme.sizes.curve * 1.3 });
      if (k >= 3 && m.join) {
        m.join.columns.forEach((c, n) => {
          const smooth = c !== 'none' && c !== 'C0';
          scene.polyline([state.x[2][n], state.x[3][n], state.y[0][n], state.y[1][n]], {
            color: smooth ? color(2) : color(1),
            width: theme.sizes.line * 1.4,
          });
        });
        // One verdict for the edge, at its middle: the weakest column decides.
        const weakest = m.join.weakest;
        const middle = state.x[3][1].map((value, i) => (value + state.x[3][2][i]) / 2);
        if (!info.thumbnail)
          scene.label(continuityName(weakest), middle, {
            dx: 12,
            dy: -16,
            color: weakest === 'none' || weakest === 'C0' ? color(1) : color(2),
            halo: true,
            bold: true,
          });
      }
      break;
    }
    case 'patch':
      break;
  }
}

const scaled = (p: readonly number[], s: number): Point => p.map((x) => x * s);

/** Marks above the handles: the tangent arrows and the normal, the first order's point to compare. */
export function drawOverConstruction(painter: Painter, m: SurfaceModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { state } = m;
  const k = state.k;
  const p = m.point;
  const label = (text: string, at: Point, color: string) => {
    if (!info.thumbnail) painter.label(text, at, { dx: 8, dy: -8, color, halo: true, bold: true });
  };
  if (state.s === 'normal') {
    const arrow = (v: readonly number[], text: string, color: string) => {
      const end = p.map((x, i) => x + v[i]);
      painter.arrow(p, end, { color, width: theme.sizes.line * 1.3 });
      label(text, end, color);
    };
    if (k >= 1) arrow(scaled(m.du, 1 / 3), '∂x/∂u', painter.color(0));
    if (k >= 2) arrow(scaled(m.dv, 1 / 3), '∂x/∂v', painter.color(1));
    if (k >= 3 && m.normal) {
      const b = m.bounds;
      const size = Math.max(b.maxX - b.minX, b.maxY - b.minY) * 0.3;
      arrow(scaled(m.normal, size), 'n', painter.color(2));
    }
  }
  if (state.s === 'casteljau' && k >= 4) {
    // The point of the first order, to compare with the second.
    painter.ring(m.uThenV.point, theme.sizes.point * 2.4, {
      color: theme.ink,
      width: theme.sizes.line,
    });
    if (k === 6) label('u then v = v then u', m.uThenV.point, theme.ink);
  }
}
