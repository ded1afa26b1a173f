import { continuityName } from '../../kit/format';
import type { Point } from '../../math';
import type { Draw } from './drawParts';
import { polygons } from './strokes';

/** A joint's continuity as written: C⁰, G¹, C¹, G², C² (or — for none). */
export const verdict = (c: string) => (c === 'none' ? '—' : continuityName(c));

/** Part 5: the hand-built pieces, then at each joint its verdict, tangents, curvature, and the comb. */
export const inspector: Draw = (painter, m, info) => {
  const { shown } = m;
  const theme = painter.theme;
  if (!shown.has('pieces')) return;
  if (shown.has('comb')) {
    for (const [a, b] of m.comb)
      painter.segment(a, b, { color: theme.palette[3], width: theme.sizes.thin });
    painter.polyline(
      m.comb.map(([, tip]) => tip),
      { color: theme.palette[3], width: theme.sizes.line },
    );
  }
  polygons(painter, m.pieces, false);
  m.pieces.forEach((piece, k) =>
    painter.cubicSegments([piece], { role: 'curve', color: painter.color(k % 2 === 0 ? 0 : 2) }),
  );
  if (!shown.has('verdicts') || info.thumbnail) return;
  m.joints.forEach((joint, k) => {
    const at = m.pieces[k][3];
    if (shown.has('tangents')) {
      painter.arrow(at, [at[0] + joint.leftVelocity[0] / 3, at[1] + joint.leftVelocity[1] / 3], {
        color: painter.color(0),
      });
      painter.arrow(at, [at[0] + joint.rightVelocity[0] / 3, at[1] + joint.rightVelocity[1] / 3], {
        color: painter.color(2),
      });
    }
    const lines = [`joint ${k + 1}: ${verdict(joint.continuity)}`];
    if (shown.is('tangents'))
      lines.push(
        joint.degenerate
          ? 'P′ = 0: no angle, no ratio'
          : `${joint.angle.toFixed(1)}°, ratio ${joint.lengthRatio.toFixed(2)}`,
      );
    if (shown.has('curvature'))
      lines.push(curvatureText(joint.leftCurvature, joint.rightCurvature));
    // One line, on the side of the joint away from its two neighbours, far enough to clear the handles.
    const k3 = 3 * (k + 1);
    const [dx, dy] = awayFrom(at, m.state.handBuilt[k3 - 1], m.state.handBuilt[k3 + 1]);
    const reach = theme.sizes.handle * 2 + theme.sizes.label;
    painter.label(lines.join(' · ').replace(/-/g, '−'), at, {
      dx: dx * reach,
      dy: -dy * reach,
      align: dx < -0.3 ? 'right' : dx > 0.3 ? 'left' : 'center',
      baseline: 'middle',
      box: true,
      size: theme.sizes.label * 0.9,
    });
  });
};

/** κ on both sides of a joint; a side whose velocity is zero has none. */
function curvatureText(left: number, right: number): string {
  if (Number.isNaN(left) && Number.isNaN(right)) return 'κ undefined (P′ = 0)';
  const side = (k: number) => (Number.isNaN(k) ? 'undefined' : k.toFixed(2));
  return `κ ${side(left)} | ${side(right)}`;
}

/** The unit direction pointing away from both neighbours of a joint (the normal where they are in line). */
function awayFrom(at: Point, before: Point, after: Point): Point {
  const unit = (v: Point): Point => {
    const size = Math.hypot(v[0], v[1]);
    return size > 0 ? [v[0] / size, v[1] / size] : [0, 0];
  };
  const a = unit([before[0] - at[0], before[1] - at[1]]);
  const b = unit([after[0] - at[0], after[1] - at[1]]);
  const sum: Point = [-(a[0] + b[0]), -(a[1] + b[1])];
  if (Math.hypot(sum[0], sum[1]) > 0.2) return unit(sum);
  // In line: below the curve if it runs right, else on the normal's side.
  const normal: Point = [b[1], -b[0]];
  return unit(normal[1] <= 0 ? normal : [-normal[0], -normal[1]]);
}
