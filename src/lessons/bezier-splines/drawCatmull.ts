import { drawLegend } from '../../kit/legend';
import { drawInset } from '../../render/inset';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import type { Draw } from './drawParts';
import type { BezierSplinesModel } from './model';

/**
 * Part 6: Hermite with hand-set tangents, then Catmull-Rom: uniform, one-sided
 * ends, centripetal, chordal, all three. Once the uniform curve is drawn, its
 * loop at the hairpin (about 15 px wide on the projector, under two handles) is
 * drawn again, magnified, in an inset.
 */
export const catmull: Draw = (painter, m, info) => {
  curves(painter, m, !info.thumbnail);
  const loop = m.alphas[0]?.loop;
  if (!m.shown.has('uniform') || !loop || info.thumbnail) return;
  drawInset(painter, { region: loop, avoid: m.state.points }, (inset) => {
    curves(inset, m, false);
    for (const p of m.state.points) inset.handle(p);
  });
};

/** The curves, tangents and crossings a step shows, and with `keyed` their key. */
function curves(painter: Painter, m: BezierSplinesModel, keyed: boolean): void {
  const { shown } = m;
  const { points: p, tangents: handSet } = m.state;
  const theme = painter.theme;
  if (!shown.has('hermite')) return;
  const tangents = (list: readonly Point[], color: string) =>
    list.forEach((t, i) => {
      if (Math.hypot(t[0], t[1]) > 0)
        painter.arrow(p[i], [p[i][0] + t[0] / 3, p[i][1] + t[1] / 3], { color });
    });
  if (shown.is('hermite')) {
    painter.cubicSegments(m.hermite, { role: 'curve' });
    tangents(handSet, theme.accent);
    return;
  }
  // The uniform step sets the hand-made Hermite spline beside the Catmull-Rom one: same form, other tangents.
  if (shown.is('uniform'))
    painter.cubicSegments(m.hermite, { color: theme.curveFaint, width: theme.sizes.line });
  const [uniform, centripetal, chordal] = m.alphas;
  if (shown.is('uniform') || shown.is('oneSided')) {
    painter.cubicSegments(uniform.segments, { role: 'curve' });
    tangents(m.crTangents, theme.accent);
    if (shown.is('oneSided')) {
      painter.cubicSegments(m.oneSided, {
        color: painter.color(3),
        width: theme.sizes.line,
        dash: [10, 6],
      });
      tangents(
        [
          m.oneSidedTangents[0],
          ...p.slice(1, -1).map(() => [0, 0]),
          m.oneSidedTangents[p.length - 1],
        ],
        painter.color(3),
      );
    }
  } else {
    // Each α step sets its spline against the uniform one; the last shows all three.
    const all = shown.is('all');
    const shownCurves = shown.is('centripetal')
      ? [uniform, centripetal]
      : shown.is('chordal')
        ? [uniform, chordal]
        : m.alphas;
    for (const curve of shownCurves) {
      const which = m.alphas.indexOf(curve);
      const main =
        (shown.is('centripetal') && which === 1) || (shown.is('chordal') && which === 2) || all;
      painter.cubicSegments(
        curve.segments,
        main
          ? { role: 'curve', color: painter.color(which) }
          : { color: theme.curveFaint, width: theme.sizes.line },
      );
    }
    if (keyed)
      // The key in the corner where it hides least (labels at the curves' ends would pile up on the last point).
      drawLegend(
        painter,
        shownCurves.map((curve) => {
          const which = m.alphas.indexOf(curve);
          const color = all || which > 0 ? painter.color(which) : theme.muted;
          return {
            text: `${curve.name}, α = ${curve.alpha}`,
            color,
            line: { color, width: theme.sizes.curve },
          };
        }),
      );
  }
  if (shown.has('uniform'))
    for (const x of uniform.crossings)
      painter.ring(x, theme.sizes.handle * 2.4, { color: theme.palette[1] });
}
