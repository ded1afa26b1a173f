import type { DrawInfo } from '../../app/lesson';
import { words } from '../../kit/format';
import { drawLegend } from '../../kit/legend';
import { pointBetween } from '../../math';
import type { Painter } from '../../render/painter';
import type { Theme } from '../../render/theme';
import { drawCursor, drawPolygon, drawSegments, ringHovered } from './drawParts';
import { nearestControl } from './meaningsGeometry';
import type { MeaningsModel } from './model';

/**
 * The two meanings of “knots” on one curve: the curve over its knot values,
 * its points at them where its pieces join (named after their u on the strip),
 * those ringed as the lecture notes' knots, the control points ringed as the
 * slides' knots, and a double ring where one is the other.
 */
export function drawMeanings(painter: Painter, m: MeaningsModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  const points = m.state.points;
  if (shown.has('values')) {
    drawPolygon(painter, points);
    drawSegments(painter, m, info);
  }
  if (shown.has('joins')) {
    // Each name round its joint, nearer it than any other joint or control
    // point: placed clear of one list of points, P(u₄) and P(u₅) stood 170 px
    // off, each nearer the other's joint.
    const radius = theme.sizes.point * 1.3;
    const rivals = [...m.knotPoints.map((k) => k.at), ...points].map(
      (p) => painter.view.toScreen(p) as [number, number],
    );
    for (const k of m.knotPoints) {
      painter.dot(k.at, theme.ink, radius);
      if (!info.thumbnail)
        painter.label(`P(u_{${k.index}})`, k.at, {
          around: radius + theme.sizes.line,
          rivals,
          color: theme.ink,
          halo: true,
        });
    }
  }
  const joinRing = theme.sizes.handle * 1.9;
  if (shown.has('lecture')) {
    for (const k of m.knotPoints)
      painter.ring(k.at, joinRing, { color: theme.ink, width: theme.sizes.line * 1.5 });
  }
  const controlRing = controlRingRadius(theme);
  if (shown.has('controls')) {
    for (const x of points)
      painter.ring(x, controlRing, { color: theme.polygon, width: theme.sizes.line * 1.5 });
  }
  // The key to the two kinds of ring, one line per meaning in its ring's colour.
  if (!info.thumbnail)
    drawLegend(painter, [
      ...(shown.has('lecture')
        ? [
            {
              text: 'P(u) at the joins: the lecture notes’ knots',
              color: theme.ink,
            },
          ]
        : []),
      ...(shown.has('controls')
        ? [{ text: 'control points: the “Splines” slides’ knots', color: theme.polygon }]
        : []),
    ]);
  if (shown.has('meet')) {
    const meet = m.knotPoints.filter((k) => k.on !== null);
    for (const k of meet)
      painter.ring(k.at, meetRingRadius(theme), {
        color: theme.accent,
        width: RING_WIDTH * theme.sizes.line,
      });
    if (meet.length === 0) {
      // None is one spot: how near the nearest pair comes.
      const { knot, point, distance } = nearestControl(m.knotPoints, points);
      painter.segment(knot.at, points[point], {
        color: theme.accent,
        width: theme.sizes.line * 1.5,
        dash: [4, 4],
      });
      if (!info.thumbnail)
        painter.label(words(distance), pointBetween(knot.at, points[point], 0.5), {
          color: theme.accent,
          halo: true,
          dx: 8,
          dy: -8,
        });
    }
  }
  if (shown.has('values')) drawCursor(painter, m, 'P(u)', info);
  ringHovered(painter, m, info);
}

/** The ring round a control point, a knot in the slides' sense. */
const controlRingRadius = (theme: Theme) => theme.sizes.handle * 2.8;
/** The ring where both meanings meet on one spot, round the other two, and its width in lines. */
const meetRingRadius = (theme: Theme) => controlRingRadius(theme) * 1.35;
const RING_WIDTH = 2;

/** How far the scene's widest mark, the ring where the meanings meet, reaches round a point. */
export const meaningsReach = (theme: Theme): number =>
  meetRingRadius(theme) + (RING_WIDTH / 2) * theme.sizes.line;
