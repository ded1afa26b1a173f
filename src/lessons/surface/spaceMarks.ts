import type { DrawInfo, Point } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import type { SpaceScene } from '../../render/space';

// Small marks in space that the constructions share.

/** Lifts a point on the surface a hair towards the viewer (figure.ts's lift). */
export type Lift = (p: readonly number[]) => Point;

/**
 * A weight's disc on a control point, its area the weight: under the point's
 * handle when it is larger (seen round it), else over it with the handle's
 * outline on top (under it, the handle hid the small weights of the edge).
 */
export function weightDisc(
  scene: SpaceScene,
  painter: Painter,
  p: readonly number[],
  radius: number,
): void {
  const accent = painter.theme.accent;
  if (radius >= painter.theme.sizes.handle) scene.dot(p, accent, radius);
  else painter.markOnHandle(p, accent, radius);
}

export const scaled = (p: readonly number[], s: number): Point => p.map((x) => x * s);

/** Named points (c₀ … c₃, r₀ … r₃), each in its colour; `named` false leaves out the names. */
export function drawPoints(
  scene: SpaceScene,
  painter: Painter,
  points: readonly Point[],
  name: string,
  info: DrawInfo,
  color: (i: number) => string,
  named = true,
) {
  const theme = painter.theme;
  points.forEach((p, i) => {
    scene.dot(p, color(i), theme.sizes.point * 1.3);
    if (named && !info.thumbnail)
      scene.label(`${name}_{${i}}`, p, {
        dx: 10,
        dy: -10,
        color: color(i),
        halo: true,
        bold: true,
      });
  });
}
