/**
 * The label placer: a label at screen coordinates goes whole inside the
 * figure, off every label placed before it, where no stroke runs through its
 * letters and, for a name, nearer its own point than any other; failing
 * that, farther out on a leader line back to its point, or boxed.
 */
import { minusSigns, say } from './notation';
import { type Box, boxesMeet, segmentMeetsBox } from './ink';
import { type LabelStyle, glyphBox, labelFrame } from './labels';
import { measureLabel } from './labelWidth';
import {
  farSpots,
  LEADER_RINGS,
  NEAR_RINGS,
  nearestIsOwn,
  nearestOnBox,
  spotsAround,
} from './labelSpots';
import type { Painter } from './painter';
import { drawLabelBox, drawLeader, insideFigure } from './labelDrawing';

/** How far a leader keeps from another label's letters (its stroke's width, and a pixel). */
const LEADER_CLEAR = 2;

/**
 * A label's letters with a hair of room above them, for a mark over a
 * capital: a stroke that passed just clear of the glyph box still touched
 * p̄'s bar, which stood on the κ plot's zero line (#19).
 */
const markRoom = (box: Box, size: number): Box => ({
  ...box,
  y: box.y - size * 0.06,
  height: box.height + size * 0.06,
});

/** Whether a stroke drawn so far runs through a label's letters at (left, middle), or its box's. */
export const struckThrough = (
  painter: Painter,
  text: string,
  left: number,
  middle: number,
  total: number,
  size: number,
  boxed: boolean,
) =>
  painter.ink.crosses(
    markRoom(
      glyphBox({ text, x: left, y: middle - size * 0.65, width: total, height: size * 1.3 }),
      size,
    ),
    boxed,
  );

/**
 * One line of a label at screen coordinates, kept whole inside the figure
 * and clear of the labels placed before it (a label wider than its figure is
 * set on lines first: screenLabel.ts).
 */
export function placeLine(
  painter: Painter,
  text: string,
  x: number,
  y: number,
  style: LabelStyle = {},
  measured = measureLabel(painter, text, style),
): { width: number } {
  const theme = painter.theme;
  const view = painter.view;
  const { size, runs, mainFont, subFont, widths, total } = measured;
  text = minusSigns(say(text));
  const align = style.align ?? 'left';
  const baseline = style.baseline ?? 'middle';
  const around = style.around ? spotsAround(x, y, style.around, total, size) : null;
  let left = around
    ? around[0][0]
    : align === 'center'
      ? x - total / 2
      : align === 'right' || align === 'end'
        ? x - total
        : x;
  let middleY = around
    ? around[0][1]
    : baseline === 'top'
      ? y + size / 2
      : baseline === 'bottom'
        ? y - size / 2
        : y;
  let boxed = style.box === true;
  // Keep the whole label inside the figure rather than cut at its edge, and
  // its box with it when it has one (asked for, or given where nothing is clear).
  const rooms = { plain: insideFigure(view, size, false), boxed: insideFigure(view, size, true) };
  const inside = (l: number, m: number): [number, number] => {
    const room = boxed ? rooms.boxed : rooms.plain;
    return [room.left(l, total), Math.max(room.top, Math.min(m, room.foot))];
  };
  [left, middleY] = inside(left, middleY);
  // A label never lands on one already placed this frame: it moves to the
  // nearest free spot around its place (above, below, beside), and if all of
  // them are taken it is left out rather than drawn unreadably on another.
  // Of the free spots it takes the first where no stroke drawn so far runs
  // through its letters (a boxed one too: its box would hide what it covers).
  const height = size * 1.3;
  // Nor does it stand against one in its row: "2" and "C²" side by side read "2C²".
  // A boxed one is as large as its box: two boxes stacked a line apart overlap.
  const apart = size * 0.3;
  const free = (l: number, m: number) => {
    const here = boxed
      ? labelFrame(l, m, total, size)
      : { x: l - apart, y: m - size * 0.65, width: total + 2 * apart, height };
    return !painter.labels.some((b) => boxesMeet(b.frame ?? b, here));
  };
  // A boxed label hides what is under its box: a place whose box covers no
  // handle (a handle must stay in reach).
  const open = (l: number, m: number) =>
    painter.ink.handlesUnder(labelFrame(...inside(l, m), total, size)) === 0;
  const unmarked = (l: number, m: number) =>
    free(l, m) && !struckThrough(painter, text, l, m, total, size, boxed) && (!boxed || open(l, m));
  // A name kept nearer its point than its rivals is kept nearer it than every
  // named point of the figure too (P(u), B₂) and every handle drawn (a line's
  // L₁ beside AP₀), wherever in the drawing they are.
  const rivals = around && style.rivals ? [...style.rivals, ...painter.named] : undefined;
  if (rivals) {
    const h = painter.ink.handles;
    for (let i = 0; i < h.length; i += 4) rivals.push([h[i], h[i + 1]]);
  }
  const own = (l: number, m: number) =>
    !rivals || nearestIsOwn({ x: l, y: m - size * 0.65, width: total, height }, x, y, rivals);
  const clear = (l: number, m: number) => unmarked(l, m) && own(l, m);
  let leaderDrawn = false;
  if (!style.inBox && !style.stays && !clear(left, middleY)) {
    if (style.fixed) return { width: 0 };
    const gap = size * 0.3;
    const shifts = [
      [0, -height],
      [0, height],
      [total + gap, 0],
      [-(total + gap), 0],
      [total + gap, -height],
      [-(total + gap), -height],
      [total + gap, height],
      [-(total + gap), height],
      [0, -2 * height],
      [0, 2 * height],
    ];
    const named = !around && style.of ? spotsAround(...style.of, size * 0.3, total, size) : [];
    // A spot the figure's edge would move far (a shift to the right of a wide
    // label near the right edge) is no longer beside its point: left out, so
    // "inflection: κ = 0" is not parked at the edge 170 px from its ring.
    const spots = (
      around ?? [...named, ...shifts.map(([dx, dy]) => [left + dx, middleY + dy])]
    ).flatMap(([l, m]): [number, number][] => {
      const [il, im] = inside(l, m);
      return Math.abs(il - l) > size || Math.abs(im - m) > size ? [] : [[il, im]];
    });
    // None near: farther out, tied to its place by a leader line; failing
    // that, its own place if no label is there, else the nearest free one.
    // A leader goes back to the point the label names (Painter.label's `of`),
    // not to where the label was first put beside it: from there, dx and dy
    // away, surface's leader to P(u,v) ended 75 px from its dot, on another.
    const [ax, ay] = around
      ? [x, y]
      : style.names && style.of
        ? style.of
        : [left + total / 2, middleY];
    let leader: [number, number] | null = null;
    let spot = spots.find(([l, m]) => clear(l, m));
    // The leader may cross lines, but no label: its stroke's width kept clear too.
    const leaderClear = (l: number, m: number) => {
      const end = nearestOnBox(ax, ay, { x: l, y: m - size * 0.65, width: total, height });
      return !painter.labels.some((b) => {
        if (b.boxed) return false;
        const g = glyphBox(b);
        const w = LEADER_CLEAR;
        const grown = { x: g.x - w, y: g.y - w, width: g.width + 2 * w, height: g.height + 2 * w };
        return segmentMeetsBox(ax, ay, end[0], end[1], grown);
      });
    };
    // The leader says whose name it is: no need to be nearest its point.
    // A heading or a value names no point: farther out it goes without one.
    const leads = around !== null || style.names === true;
    const far = (fits: (l: number, m: number) => boolean) => {
      const found = farSpots(ax, ay, total, height, leads ? LEADER_RINGS : NEAR_RINGS)
        .map(([l, m]) => inside(l, m))
        .find(([l, m]) => fits(l, m) && (!leads || leaderClear(l, m)));
      if (found && leads) leader = [ax, ay];
      return found;
    };
    if (!spot && style.optional) return { width: 0 };
    if (!spot && !style.box) spot = far(unmarked);
    // Nowhere clear within reach: it keeps a free place and is boxed, so the
    // lines under it cannot be read as part of it, where its box hides no
    // handle: near and nearest its own point, else farther out with a leader
    // (which says whose name it is), else near after all.
    if (!spot) boxed = true;
    const places: [number, number][] = [[left, middleY], ...spots];
    spot ??=
      places.find(([l, m]) => free(l, m) && own(l, m) && open(l, m)) ??
      far((l, m) => free(l, m) && open(l, m)) ??
      places.find(([l, m]) => free(l, m) && open(l, m)) ??
      places.find(([l, m]) => free(l, m) && own(l, m)) ??
      places.find(([l, m]) => free(l, m));
    if (!spot) return { width: 0 };
    [left, middleY] = boxed ? inside(...spot) : spot;
    // Shifted a whole label's width from where it was put, a name can stand
    // far from its point with nothing to say whose it is (bezier-properties'
    // "inflection, u = 0.50", 300 px from its dot): a leader goes back to it.
    if (!leader && leads && style.of) {
      const [px, py] = style.of;
      const [ex, ey] = nearestOnBox(px, py, {
        x: left,
        y: middleY - size * 0.65,
        width: total,
        height,
      });
      if (Math.hypot(ex - px, ey - py) > size * 1.5 && leaderClear(left, middleY))
        leader = [px, py];
    }
    leaderDrawn = leader !== null;
    if (leader)
      drawLeader(
        painter,
        leader,
        { x: left, y: middleY - size * 0.65, width: total, height },
        style.color,
      );
  }
  const c = painter.ctx;
  c.save();
  c.setLineDash([]);
  c.globalAlpha = 1;
  // The box as drawn, and as the placer keeps later labels off it.
  const frame = boxed ? labelFrame(left, middleY, total, size) : null;
  if (!style.inBox)
    painter.labels.push({
      text,
      x: left,
      y: middleY - size * 0.65,
      width: total,
      height,
      ...(boxed ? { boxed: true } : {}),
      ...(around ? { anchor: [x, y] as [number, number] } : {}),
      ...(leaderDrawn ? { leader: true } : {}),
      ...(frame ? { frame } : {}),
    });
  if (frame) drawLabelBox(painter, frame, style.color);
  c.textAlign = 'left';
  c.textBaseline = 'middle';
  runs.forEach((run, i) => {
    c.font = run.sub ? subFont : mainFont;
    const textY = run.sub ? middleY + size * 0.3 : middleY;
    if (style.halo && !boxed) {
      // A halo that follows the glyphs, as map labels have: it keeps the text
      // readable over lines without blanking out a rectangle of the figure.
      c.strokeStyle = theme.labelHalo;
      c.lineWidth = Math.max(2.5, size * 0.22);
      c.lineJoin = 'round';
      c.globalAlpha = 0.9;
      c.strokeText(run.text, left, textY);
      c.globalAlpha = 1;
    }
    c.fillStyle = style.color ?? theme.ink;
    c.fillText(run.text, left, textY);
    left += widths[i];
  });
  c.restore();
  return { width: total };
}
