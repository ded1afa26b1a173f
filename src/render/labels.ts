/**
 * Placing text on a figure: lecture labels with subscripts, labels that keep
 * clear of nearby handles, values beside a plot cursor pushed apart, and
 * boxed notes. Every placed label's box is recorded on the painter, so tests
 * can check that no two overlap.
 */
import { say } from './notation';
import { type Box, boxesMeet, segmentMeetsBox } from './ink';
import type { Painter } from './painter';
import type { DrawingSurface } from './surface';
import { subscriptNames } from '../kit/subscripts';

export interface LabelStyle {
  color?: string;
  size?: number;
  /** Offset in pixels from the anchor (screen axes, y down). */
  dx?: number;
  dy?: number;
  align?: CanvasTextAlign;
  baseline?: CanvasTextBaseline;
  bold?: boolean;
  /** Draw a light halo behind the text so it reads over lines. */
  halo?: boolean;
  /** Draw a boxed label (background box with border). */
  box?: boolean;
  /**
   * The anchor is a point drawn with this radius (px), and the label goes
   * beside it on whichever side is clear: above right first, then below
   * right, above left, below left, right, left, above, below.
   */
  around?: number;
  /**
   * Other named points on screen (pixels). A label placed `around` its point
   * goes only where it is nearer its own point than any of these, and than
   * any point the figure names (`Painter.namedPoint`) or handle it has drawn,
   * so P₃'s name beside P₄ is never read as P₄'s; failing that it goes
   * farther out on a leader line from its point.
   */
  rivals?: readonly (readonly [number, number])[];
  /** It stays where it is put (an axis number at its tick), or is left out. */
  fixed?: boolean;
  /**
   * It stays where it is put even where that is not clear: its caller chose
   * the place that hides least (a plot's values, boxed over a dashed line
   * rather than over the curve, and never moved across the cursor's line).
   */
  stays?: boolean;
  /**
   * It names the point it was asked at (`Painter.label`, or `around`): moved
   * away, a leader line back to there says whose it is. A heading or a value
   * at a screen position names no point: moved away, it goes without one
   * (raster's heading hung from a leader to nothing).
   */
  names?: boolean;
  /**
   * Where the point it names is on screen (`Painter.label` says): moved from
   * its first place, it tries places all round that point before it goes
   * farther, rather than shifting a label's width at a time away from it.
   */
  of?: readonly [number, number];
  /**
   * It is said elsewhere too (a number the step's formula or table also
   * shows): where no place near it is clear, it is left out rather than boxed
   * over the figure or sent out on a leader (a phone's crowded patch).
   */
  optional?: boolean;
  /**
   * It is part of a box already drawn and registered (a legend's names): it
   * goes exactly where it is put, and the box stands for it among the labels.
   */
  inBox?: boolean;
}

/** Where a label went, in screen pixels. */
export interface LabelBox {
  text: string;
  x: number;
  y: number;
  width: number;
  height: number;
  /** Drawn on a box of its own (a boxed value, a note), which covers what lies under it. */
  boxed?: boolean;
  /** The point it names, for a label placed beside one (`around`), in screen pixels. */
  anchor?: [number, number];
  /** Tied to that point by a leader line. */
  leader?: boolean;
  /** A boxed label's box as drawn, wider and taller than its letters. */
  frame?: Box;
}

/** Squared distance from (x, y) to the nearest point of a box. */
function distanceToBox2(x: number, y: number, box: Box): number {
  const dx = Math.max(box.x - x, 0, x - (box.x + box.width));
  const dy = Math.max(box.y - y, 0, y - (box.y + box.height));
  return dx * dx + dy * dy;
}

/**
 * Is a label's box at least as near its own point (ax, ay) as any of the
 * other points? A name nearer another point is read as that point's.
 */
function nearestIsOwn(
  box: Box,
  ax: number,
  ay: number,
  others: readonly (readonly [number, number])[],
): boolean {
  const own = distanceToBox2(ax, ay, box);
  for (const [x, y] of others) {
    if (x === ax && y === ay) continue;
    // Cheap reject first: a point farther off on either axis cannot be nearer.
    const dx = Math.max(box.x - x, 0, x - (box.x + box.width));
    if (dx * dx >= own) continue;
    const dy = Math.max(box.y - y, 0, y - (box.y + box.height));
    if (dx * dx + dy * dy < own) return false;
  }
  return true;
}

/**
 * The part of a label's box its letters fill (capitals to the foot of a
 * subscript), without the line spacing around them: what no stroke may cross.
 */
export function glyphBox(b: LabelBox): Box {
  return { x: b.x, y: b.y + b.height * 0.18, width: b.width, height: b.height * 0.7 };
}

/** Splits `P_{1,2}x_3` into runs of normal and subscript text. */
export function splitSubscripts(text: string): { text: string; sub: boolean }[] {
  const runs: { text: string; sub: boolean }[] = [];
  let i = 0;
  let plain = '';
  while (i < text.length) {
    if (text[i] === '_' && i + 1 < text.length) {
      if (plain) runs.push({ text: plain, sub: false });
      plain = '';
      if (text[i + 1] === '{') {
        const end = text.indexOf('}', i + 2);
        const stop = end < 0 ? text.length : end;
        runs.push({ text: text.slice(i + 2, stop), sub: true });
        i = stop + 1;
      } else {
        runs.push({ text: text[i + 1], sub: true });
        i += 2;
      }
    } else {
      plain += text[i];
      i += 1;
    }
  }
  if (plain) runs.push({ text: plain, sub: false });
  return runs;
}

/** How many labels placed so far lie under the box. */
const labelsUnder = (painter: Painter, box: Box) =>
  painter.labels.filter((b) => boxesMeet(b, box)).length;

/**
 * Of the places a box may go over the figure (a note, a key, a plot's name),
 * the first under which no stroke, point or label lies; -1 if none is clear.
 * A drawn box may cover the grid's axes; letters without one (`covers`
 * false: a heading) may not.
 */
export function firstClear(painter: Painter, boxes: readonly Box[], covers = true): number {
  return boxes.findIndex(
    (box) => labelsUnder(painter, box) === 0 && !painter.ink.crosses(box, covers),
  );
}

/**
 * The place that hides least (-1 if none): a handle hidden is worse than
 * anything else (it can no longer be grabbed), a point or a label worse than
 * any number of strokes crossed (the curve shows round it).
 */
export function leastHidden(painter: Painter, boxes: readonly Box[]): number {
  const hidden = boxes.map((box) => {
    const { discs, strokes } = painter.ink.hits(box);
    return (
      painter.ink.handlesUnder(box) * 1e6 + (discs + labelsUnder(painter, box)) * 1000 + strokes
    );
  });
  return hidden.indexOf(Math.min(...hidden));
}

/**
 * Where a box `width` × `height` may sit over a figure `margin` from its
 * edges: the four corners (top left first), then the middles of the top and
 * foot, then of the sides, for when every corner holds a handle. `top` is
 * the least y at the top (below a box already there).
 */
export function edgePlaces(
  view: { width: number; height: number },
  width: number,
  height: number,
  margin: number,
  top = margin,
): Box[] {
  const [right, foot] = [view.width - width - margin, view.height - height - margin];
  const [centre, middle] = [(view.width - width) / 2, (top + foot) / 2];
  return [
    [margin, top],
    [right, top],
    [margin, foot],
    [right, foot],
    [centre, top],
    [centre, foot],
    [margin, middle],
    [right, middle],
  ].map(([x, y]) => ({ x, y, width, height }));
}

/** The first clear place, else the one that hides least. */
export const clearestPlace = (painter: Painter, boxes: readonly Box[]): number => {
  const clear = firstClear(painter, boxes);
  return clear >= 0 ? clear : leastHidden(painter, boxes);
};

/** The box drawn round a boxed label `total` wide, its text's middle at (left, middleY). */
function labelFrame(left: number, middleY: number, total: number, size: number): Box {
  const pad = size * 0.35;
  return {
    x: left - pad,
    y: middleY - size * 0.62 - pad * 0.4,
    width: total + 2 * pad,
    height: size * 1.3 + pad * 0.8,
  };
}

/** The fonts and runs of a label, and its width in pixels. */
function measure(painter: Painter, text: string, style: LabelStyle) {
  const theme = painter.theme;
  const c = painter.ctx;
  // No text under the theme's least size, subscripts included.
  const least = theme.sizes.minText ?? 0;
  const size = Math.max(style.size ?? theme.sizes.label, least);
  const runs = splitSubscripts(say(text));
  const weight = style.bold ? 'bold ' : '';
  const mainFont = `${weight}${size}px ${theme.fontFamily}`;
  const subFont = `${weight}${Math.max(Math.round(size * 0.78), least)}px ${theme.fontFamily}`;
  const widths = runs.map((run) => textWidth(c, run.sub ? subFont : mainFont, run.text));
  const total = widths.reduce((a, b) => a + b, 0);
  return { size, runs, mainFont, subFont, widths, total };
}

/**
 * Widths of text on screen canvases, by font and text: the same on every
 * canvas (system fonts, nothing loaded later), and a label is measured on
 * every frame it is drawn (a surface's 20 names: 1 ms of a drag frame). An
 * SVG export or a test's recording measures its own way, every time.
 */
const screenWidths = new Map<string, number>();
const MAX_WIDTHS = 4096;

/** The width of `text` in `font` (px) on the surface `c`; its font is left as it was. */
function textWidth(c: DrawingSurface, font: string, text: string): number {
  const screen =
    typeof CanvasRenderingContext2D !== 'undefined' && c instanceof CanvasRenderingContext2D;
  const key = `${font}\n${text}`;
  const known = screen ? screenWidths.get(key) : undefined;
  if (known !== undefined) return known;
  c.save();
  c.font = font;
  const width = c.measureText(text).width;
  c.restore();
  if (screen) {
    if (screenWidths.size >= MAX_WIDTHS) screenWidths.clear();
    screenWidths.set(key, width);
  }
  return width;
}

/** How wide a label will be (px), before it is placed. */
export function labelWidth(painter: Painter, text: string, style: LabelStyle = {}): number {
  return measure(painter, text, style).total;
}

/**
 * Places beside a point drawn with radius `r` at (x, y), in the order tried:
 * [left, middle] of the label.
 */
function spotsAround(x: number, y: number, r: number, total: number, size: number) {
  const spots: [number, number][] = [];
  // Close beside the point first, then a little farther out (past a ring or
  // a line that hugs it).
  for (const far of [0, size * 0.7]) {
    const d = r * 0.75 + 3 + far;
    const up = y - d - size * 0.45;
    const down = y + d + size * 0.45;
    spots.push(
      [x + d, up],
      [x + d, down],
      [x - d - total, up],
      [x - d - total, down],
      [x + r + far + size * 0.3, y],
      [x - r - far - size * 0.3 - total, y],
      [x - total / 2, y - r - far - size * 0.75],
      [x - total / 2, y + r + far + size * 0.75],
    );
  }
  return spots;
}

/**
 * Places farther from a label's anchor (its centre at (ax, ay)), ring after
 * ring, each ring's twelve directions from above round clockwise: [left,
 * middle] of the label.
 */
function farSpots(ax: number, ay: number, total: number, height: number): [number, number][] {
  const spots: [number, number][] = [];
  for (const reach of [1.6, 2.4, 3.4]) {
    for (let k = 0; k < 12; k++) {
      const angle = -Math.PI / 2 + (k * Math.PI) / 6;
      const cx = ax + Math.cos(angle) * (reach * height + total / 2);
      const cy = ay + Math.sin(angle) * reach * height;
      spots.push([cx - total / 2, cy]);
    }
  }
  return spots;
}

/** The point of a box nearest to (x, y). */
function nearestOnBox(x: number, y: number, box: Box): [number, number] {
  return [
    Math.max(box.x, Math.min(x, box.x + box.width)),
    Math.max(box.y, Math.min(y, box.y + box.height)),
  ];
}

/** A thin line from a label's anchor to the nearest point of its box (when it had to move away). */
/** How far a leader keeps from another label's letters (its stroke's width, and a pixel). */
const LEADER_CLEAR = 2;

function drawLeader(painter: Painter, [ax, ay]: [number, number], box: Box, color?: string): void {
  const [ex, ey] = nearestOnBox(ax, ay, box);
  // It stops a little short of the label's box.
  const length = Math.hypot(ex - ax, ey - ay);
  const k = length > 4 ? (length - 4) / length : 0;
  const [bx, by] = [ax + (ex - ax) * k, ay + (ey - ay) * k];
  const c = painter.ctx;
  c.save();
  c.setLineDash([]);
  c.globalAlpha = 0.7;
  c.strokeStyle = color ?? painter.theme.ink;
  c.lineWidth = Math.max(1, painter.theme.sizes.thin * 0.6);
  c.beginPath();
  c.moveTo(ax, ay);
  c.lineTo(bx, by);
  c.stroke();
  c.restore();
  painter.ink.segment(ax, ay, bx, by, c.lineWidth / 2);
}

/** A label at screen coordinates, kept whole inside the figure and clear of the labels placed before it. */
export function drawScreenLabel(
  painter: Painter,
  text: string,
  x: number,
  y: number,
  style: LabelStyle = {},
): { width: number } {
  const theme = painter.theme;
  const view = painter.view;
  const { size, runs, mainFont, subFont, widths, total } = measure(painter, text, style);
  text = say(text);
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
  const inside = (l: number, m: number): [number, number] => {
    const margin = 2 + (boxed ? size * 0.35 : 0);
    return [
      Math.max(margin, Math.min(l, view.width - total - margin)),
      Math.max(size * 0.7 + margin, Math.min(m, view.height - size * 0.7 - margin)),
    ];
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
    free(l, m) &&
    !painter.ink.crosses(
      glyphBox({ text, x: l, y: m - size * 0.65, width: total, height }),
      boxed,
    ) &&
    (!boxed || open(l, m));
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
    const [ax, ay] = around ? [x, y] : [left + total / 2, middleY];
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
      const found = farSpots(ax, ay, total, height)
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
  if (frame) {
    const box = [frame.x, frame.y, frame.width, frame.height] as const;
    c.fillStyle = theme.labelHalo;
    c.globalAlpha = 0.92;
    c.fillRect(...box);
    c.globalAlpha = 1;
    c.strokeStyle = style.color ?? theme.ink;
    c.lineWidth = Math.max(1, theme.sizes.thin);
    c.beginPath();
    c.rect(...box);
    c.stroke();
  }
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

/**
 * A box drawn over the figure for words in it (a note, a key): the
 * background all but opaque, and a border.
 */
export function drawPanelBox(
  painter: Painter,
  box: { x: number; y: number; width: number; height: number },
  border: string,
  borderWidth: number,
): void {
  const c = painter.ctx;
  c.save();
  c.setLineDash([]);
  c.globalAlpha = 0.94;
  c.fillStyle = painter.theme.labelHalo;
  c.fillRect(box.x, box.y, box.width, box.height);
  c.globalAlpha = 1;
  c.strokeStyle = border;
  c.lineWidth = borderWidth;
  c.beginPath();
  c.rect(box.x, box.y, box.width, box.height);
  c.stroke();
  c.restore();
}

/** How a note is drawn: its border's colour, its top (stacked notes), and words for a small figure. */
export interface NoteStyle {
  color?: string;
  /** Given, it sits there at the left. */
  top?: number;
  /** The same said briefly, for a figure too small to hold the whole clear of its handles. */
  brief?: string;
}

/**
 * A note's widths to try, as shares of its figure's: a corner's note, not a
 * banner, then narrower; a banner only when no corner of those is clear (the
 * band a figure keeps free above its curve for a note, #19).
 */
const NOTE_SHARES = [0.6, 0.45, 0.34, 0.26, 0.96];

/**
 * A boxed, word-wrapped message in a corner of the figure; returns the y
 * below it were it at the top left. Given a `top`, it sits there at the left
 * (notes stacked one under another). Otherwise it waits, as labels do, until
 * the figure and its handles are drawn, and takes the first corner (top left,
 * top right, foot left, foot right) where no stroke, point or label runs
 * under it (#19: across the top it covered control points and villages),
 * wrapped as wide as three fifths of the figure or, failing that, narrower
 * and taller (the empty sides of a wide figure); if no corner is clear at any
 * width, the place that hides least.
 */
/**
 * A note's words as the page writes them: the reader's letters, and points
 * named with subscripts (the page's own text turns "P2 = P3" into "P₂ = P₃";
 * the same note on the figure read "P2").
 */
const prose = (text: string) => subscriptNames(say(text));

export function drawNote(painter: Painter, full: string, style: NoteStyle = {}): number {
  const c = painter.ctx;
  const theme = painter.theme;
  const { width: figureWidth, height: figureHeight } = painter.view;
  /** `text` in `size` px wrapped to at most a `share` of the figure's width: its lines and box. */
  const wrapAt = (share: number, size = theme.sizes.label, text = prose(full)) => {
    const words = text.split(/\s+/).filter(Boolean);
    const pad = size * 0.5;
    const maxWidth = Math.max(size * 6, Math.min(figureWidth - 4 * pad, figureWidth * share));
    // Measured through the screen's cache: a note that finds no clear place
    // wraps itself up to 20 ways a frame, each time the same.
    const font = `${size}px ${theme.fontFamily}`;
    const lines: string[] = [];
    for (const word of words) {
      const last = lines.length ? `${lines[lines.length - 1]} ${word}` : word;
      if (lines.length && textWidth(c, font, last) <= maxWidth) lines[lines.length - 1] = last;
      else lines.push(word);
    }
    const width = Math.max(...lines.map((line) => textWidth(c, font, line)), 0);
    return {
      text,
      size,
      pad,
      lines,
      width: width + 2 * pad,
      height: lines.length * size * 1.3 + pad,
    };
  };
  type Wrapped = ReturnType<typeof wrapAt>;
  const widest = wrapAt(NOTE_SHARES[0]);
  const draw = (note: Wrapped, x: number, top: number) => {
    const { text, width, height } = note;
    painter.labels.push({ text, x, y: top, width, height, boxed: true });
    drawPanelBox(
      painter,
      { x, y: top, width: note.width, height: note.height },
      style.color ?? theme.accent,
      Math.max(2, theme.sizes.line),
    );
    c.save();
    c.font = `${note.size}px ${theme.fontFamily}`;
    c.fillStyle = theme.ink;
    c.textAlign = 'left';
    c.textBaseline = 'middle';
    note.lines.forEach((line, i) =>
      c.fillText(line, x + note.pad, top + note.pad / 2 + (i + 0.5) * note.size * 1.3),
    );
    c.restore();
  };
  if (style.top !== undefined) {
    draw(widest, widest.pad, style.top);
    return style.top + widest.height + widest.pad;
  }
  painter.placing(() => {
    // Widest first; a narrower wrap only when no corner of the wider one is
    // clear; then the same in the figure's small size, then the brief words
    // (a phone's small figure), before a handle is hidden.
    const tried: { note: Wrapped; box: Box }[] = [];
    const texts = style.brief ? [prose(full), prose(style.brief)] : [prose(full)];
    for (const text of texts)
      for (const size of new Set([theme.sizes.label, theme.sizes.small]))
        for (const share of NOTE_SHARES) {
          const first = text === texts[0] && size === theme.sizes.label && share === NOTE_SHARES[0];
          const note = first ? widest : wrapAt(share, size, text);
          if (tried.length && note.height > figureHeight - 2 * note.pad) continue;
          const corners = edgePlaces(painter.view, note.width, note.height, note.pad).filter(
            ({ x, y }) => x >= 0 && y >= 0,
          );
          const clear = firstClear(painter, corners);
          if (clear >= 0) return draw(note, corners[clear].x, corners[clear].y);
          tried.push(...corners.map((box) => ({ note, box })));
        }
    // No corner is clear: the place that hides least.
    const best =
      tried[
        leastHidden(
          painter,
          tried.map(({ box }) => box),
        )
      ];
    if (best) draw(best.note, best.box.x, best.box.y);
    else draw(widest, widest.pad, widest.pad);
  });
  return widest.pad + widest.height + widest.pad;
}

/**
 * A label beside the screen point `at` on whichever of four sides
 * (above/below, right/left) lies farthest from the `avoid` points (world).
 */
export function drawLabelClear(
  painter: Painter,
  text: string,
  at: readonly [number, number],
  avoid: readonly (readonly number[])[],
  style: LabelStyle = {},
): void {
  const [x, y] = at;
  const size = style.size ?? painter.theme.sizes.label;
  const width = size * 0.6 * text.length;
  const gap = size * 0.7;
  const candidates: [number, number, CanvasTextAlign][] = [
    [gap, -size, 'left'],
    [gap, size, 'left'],
    [-gap, -size, 'right'],
    [-gap, size, 'right'],
  ];
  const obstacles = avoid.map((q) => painter.view.toScreen(q));
  let best = candidates[0];
  let bestClearance = -Infinity;
  for (const candidate of candidates) {
    const [dx, dy, align] = candidate;
    const cx = x + dx + (align === 'left' ? width / 2 : -width / 2);
    const cy = y + dy;
    let clearance = Infinity;
    for (const [ox, oy] of obstacles) clearance = Math.min(clearance, Math.hypot(ox - cx, oy - cy));
    if (clearance > bestClearance + 1e-9) {
      bestClearance = clearance;
      best = candidate;
    }
  }
  drawScreenLabel(painter, text, x + best[0], y + best[1], { ...style, align: best[2] });
}
