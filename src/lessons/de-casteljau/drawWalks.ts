import type { DrawInfo } from '../../app/lesson';
import { pointWords, words } from '../../kit/format';
import { handleLabelBoxes, placeLabel } from '../../kit/labels';
import { levelColour, levelDash } from '../../kit/seriesColours';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import type { DeCasteljauModel } from './model';

/** Every computed point is named up to this degree; beyond, only the ones the step is about. */
const NAME_ALL_UP_TO = 5;

const name = (r: number, i: number) => `P_{${r},${i}}`;

/** The computed part of each level: its polyline and its points, in the level's colour. */
function drawLevels(painter: Painter, levels: readonly Point[][], computed: readonly number[]) {
  const theme = painter.theme;
  if (computed[0] > 0)
    painter.polyline(levels[0], { color: theme.polygon, width: theme.sizes.line, dash: [6, 5] });
  for (let r = 1; r < levels.length; r++) {
    const done = levels[r].slice(0, computed[r]);
    const color = levelColour(theme.palette, r);
    painter.polyline(done, { color, width: theme.sizes.line, dash: levelDash(r) });
    done.forEach((point) => painter.dot(point, color, theme.sizes.point));
  }
}

/** P(t), the construction's last point, large and in the accent. */
const drawPoint = (painter: Painter, m: DeCasteljauModel) =>
  painter.movingPoint(m.levels[m.n][0], 1.6);

/**
 * The pseudocode's run so far: level 0 once line 1 has copied it, every
 * point line 4 has computed, the edge the current step cuts (wide) and its
 * new point with its numbers; the point returned; drawCurve's plotted points.
 */
export function drawPseudocode(painter: Painter, m: DeCasteljauModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { levels, shown, computed, current, n } = m;
  if (shown.has('plot')) {
    painter.polylineFlat(m.curve, { color: theme.curveFaint, role: 'curve' });
    m.plotted.forEach((point) => painter.dot(point, theme.ink, theme.sizes.point * 0.8));
  }
  for (const [r, i] of current) {
    painter.segment(levels[r - 1][i], levels[r - 1][i + 1], {
      color: levelColour(theme.palette, r),
      width: theme.sizes.line * 3,
      alpha: 0.45,
    });
  }
  drawLevels(painter, levels, computed);
  if (shown.has('return')) drawPoint(painter, m);
  if (info.thumbnail) return;

  const named: [number, number, string][] = [];
  const returned = shown.has('return') ? levels[n][0] : null;
  if (returned) named.push([n, 0, `${name(n, 0)} = P(t) = ${pointWords(returned)}`]);
  const one = current.length === 1;
  for (const [r, i] of current)
    named.push([r, i, one ? `${name(r, i)} = ${pointWords(levels[r][i])}` : name(r, i)]);
  if (n <= NAME_ALL_UP_TO)
    computed.forEach((count, r) => {
      for (let i = 0; r > 0 && i < count; i++)
        if (!named.some(([a, b]) => a === r && b === i)) named.push([r, i, name(r, i)]);
    });
  const avoid = levels.flatMap((level, r) => level.slice(0, computed[r]));
  const taken = handleLabelBoxes(painter, m.state.p);
  named.forEach(([r, i, text], k) =>
    placeLabel(
      painter,
      text,
      levels[r][i],
      avoid,
      {
        color: r === n ? theme.ink : levelColour(theme.palette, r),
        halo: true,
        bold: k === 0,
        size: theme.sizes.label * 0.9,
      },
      taken,
    ),
  );
}

/**
 * The expansion level by level: the levels so far (the earlier ones faint),
 * the current level's first point tied to the control points it blends, each
 * labelled with its weight W(r, j, t); at the end the construction itself,
 * landing on the same point, and the curve.
 */
export function drawBernstein(painter: Painter, m: DeCasteljauModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { state, n, blends, weights, shown } = m;
  const same = shown.has('same');
  const r = same ? n : shown.count('blend');
  if (r === 0) return;
  if (same) {
    painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
    drawLevels(
      painter,
      m.levels,
      m.levels.map((level) => level.length),
    );
  } else {
    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.line, dash: [6, 5] });
    for (let k = 1; k <= r; k++) {
      const color = levelColour(theme.palette, k);
      const style = { color, width: theme.sizes.line, dash: levelDash(k) };
      painter.polyline(blends[k], k < r ? { ...style, alpha: 0.35 } : style);
      blends[k].forEach((point) =>
        painter.dot(point, color, theme.sizes.point * (k < r ? 0.7 : 1)),
      );
    }
  }
  const color = levelColour(theme.palette, r);
  const target = blends[r][0];
  for (let j = 0; j <= r; j++)
    painter.segment(target, state.p[j], { color, width: theme.sizes.line * 0.8, dash: [3, 4] });
  if (r === n) drawPoint(painter, m);
  if (info.thumbnail) return;

  const taken = handleLabelBoxes(painter, state.p);
  const avoid = [...state.p, ...blends[r]];
  const style = { color, halo: true, size: theme.sizes.label * 0.9 };
  const point =
    r === n
      ? `${name(n, 0)} = P(t) = ${pointWords(target)}`
      : `${name(r, 0)} = ${pointWords(target)}`;
  placeLabel(painter, point, target, avoid, { ...style, color: theme.ink, bold: true }, taken);
  weights[r].forEach((w, j) =>
    placeLabel(painter, `${words(w)}·P_{${j}}`, state.p[j], avoid, style, taken),
  );
}
