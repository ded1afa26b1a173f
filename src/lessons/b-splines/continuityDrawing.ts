import type { DrawInfo } from '../../app/lesson';
import { words } from '../../kit/format';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import { boundsOf, diagonal } from '../../render/projection';
import { derivativeName, smoothName } from './continuityScript';
import { drawCursor, drawPolygon, drawSegments, ringHovered } from './drawParts';
import type { ContinuityModel } from './model';

/** The longest of the two arrows, as a share of the control points' extent. */
const ARROW_SHARE = 0.2;

/**
 * The first derivative that differs at the watched knot, left and right, as
 * two arrows from the join drawn to one scale, each in its piece's colour.
 */
function differingArrows(painter: Painter, m: ContinuityModel, info: DrawInfo): void {
  const check = m.watched;
  const r = check.smooth + 1;
  if (!(r < check.left.length)) return;
  const extent = diagonal(boundsOf(m.state.points));
  const left = check.left[r];
  const right = check.right[r];
  const longest = Math.max(Math.hypot(...left), Math.hypot(...right));
  if (!(longest > 0)) return;
  const scale = (ARROW_SHARE * extent) / longest;
  const sides: [Point, number, string][] = [
    [left, check.before, '⁻'],
    [right, check.after, '⁺'],
  ];
  for (const [vector, segment, side] of sides) {
    const tip: Point = [check.at[0] + scale * vector[0], check.at[1] + scale * vector[1]];
    const color = painter.color(segment);
    painter.arrow(check.at, tip, { color, width: painter.theme.sizes.line * 1.8 });
    if (!info.thumbnail)
      painter.label(`${derivativeName(r)}(${words(check.u)}${side})`, tip, {
        color,
        halo: true,
        dx: 6,
        dy: -6,
      });
  }
}

/**
 * Degree p ⇒ Cᵖ⁻¹: the step's curve, every knot inside it labelled with the
 * continuity its derivatives show, the watched knot ringed with the first
 * derivative that breaks there, and the control point a triple knot passes through.
 */
export function drawContinuity(painter: Painter, m: ContinuityModel, info: DrawInfo): void {
  const theme = painter.theme;
  if (!m.shown.is('points')) {
    drawPolygon(painter, m.state.points);
    drawSegments(painter, m, info);
    for (const check of m.checks) {
      painter.dot(check.at, theme.ink, theme.sizes.point);
      if (!info.thumbnail)
        painter.label(smoothName(check.smooth), check.at, {
          dx: 10,
          dy: 22,
          color: theme.ink,
          halo: true,
          box: check.smooth <= 0,
        });
    }
    const check = m.watched;
    painter.ring(check.at, theme.sizes.handle * 2.2, {
      color: theme.accent,
      width: theme.sizes.line * 2,
    });
    if (check.through !== null)
      painter.ring(m.state.points[check.through], theme.sizes.handle * 3, {
        color: theme.accent,
        width: theme.sizes.line * 1.5,
      });
    differingArrows(painter, m, info);
    drawCursor(painter, m, 'P(u)', info);
  }
  ringHovered(painter, m, info);
}
